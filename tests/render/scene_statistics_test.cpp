// What `lamina info` counts (scene_statistics.h): shapes, emitting shapes and the area lights
// they become, materials with
// their lobes, what the polarised mode makes of them and whether a shape uses them, the
// spectral data of the used ones, and the film's memory at the scene's resolution.
#include <gtest/gtest.h>

#include "lamina/core/json_reader.h"
#include "lamina/render/scene_statistics.h"

namespace lamina::render {
namespace {

TEST(SceneStatistics, CountsWhatTheSceneHolds) {
    const SceneDesc scene = parseScene(R"({
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
      "film": {"resolution": [16, 8]},
      "materials": {"gold": {"type": "conductor", "material": "Au"},
                    "matte": {"type": "lambert"},
                    "spare": {"type": "conductor", "material": "Cu"}},
      "shapes": [
        {"type": "sphere", "radius": 1, "material": "gold"},
        {"type": "rectangle", "material": "matte", "transform": [{"translate": [0, 3, 0]}],
         "emission": {"radiance": 1}},
        {"type": "mesh", "material": "matte", "positions": [[0, 0, 5], [1, 0, 5], [0, 1, 5],
         [1, 1, 6]], "faces": [[0, 1, 2], [1, 3, 2]], "emission": {"radiance": 1}}
      ]
    })",
                                       JsonSource{"<test>", "."});
    const SceneStatistics s = sceneStatistics(scene);
    EXPECT_EQ(s.spheres, 1u);
    // The rectangle is a mesh of two triangles and one light, as written; the bent mesh of two
    // triangles (no rectangle) is one shape and two triangle lights.
    EXPECT_EQ(s.meshes, 2u);
    EXPECT_EQ(s.triangles, 4u);
    EXPECT_EQ(s.vertices, 8u);
    EXPECT_EQ(s.emitters, 2u);
    EXPECT_EQ(s.areaLights, 3u);
    EXPECT_EQ(s.lights, 0u);
    EXPECT_GT(s.geometryBytes, 0u);
    EXPECT_EQ(s.film.total(), estimateRenderMemory(16, 8, false, false).total());
    EXPECT_EQ(s.filmWithAovs, estimateRenderMemory(16, 8, true, false).total());
    ASSERT_EQ(s.materials.size(), scene.materials.size());
    for (const auto& m : s.materials) {
        EXPECT_FALSE(m.lobes.empty()) << m.name;
        EXPECT_EQ(m.used, m.name != "spare") << m.name;
        // What the polarised mode makes of each (docs/polarisation.md): the conductors
        // polarise by their Fresnel amplitudes, the diffuse lobe is an ideal depolariser.
        EXPECT_EQ(m.polarisation.starts_with("polarising"), m.type == "conductor") << m.name;
        if (m.type == "lambert") {
            EXPECT_EQ(m.polarisation, "an ideal depolariser");
        }
    }
    // The used conductor's n, k; the unused one's not.
    ASSERT_EQ(s.spectralData.size(), 1u);
    EXPECT_NE(s.spectralData[0].find("(n, k)"), std::string::npos) << s.spectralData[0];
}

// pbrt-v4's quadrics are counted by kind; a sphere or disk whose clipping keys leave it whole
// is an analytic sphere or disk; an emitting quadric is one area light.
TEST(SceneStatistics, CountsQuadricsByKind) {
    const SceneDesc scene = parseScene(R"({
      "materials": {"matte": {"type": "lambert"}},
      "shapes": [
        {"type": "sphere", "material": "matte", "z_max": 0.5},
        {"type": "sphere", "material": "matte", "phi_max": 360},
        {"type": "cylinder", "material": "matte", "emission": {"radiance": 1}},
        {"type": "cylinder", "material": "matte", "phi_max": 90},
        {"type": "disk", "material": "matte", "inner_radius": 0.5},
        {"type": "disk", "material": "matte", "inner_radius": 0}
      ]
    })",
                                       JsonSource{"<test>", "."});
    const SceneStatistics s = sceneStatistics(scene);
    EXPECT_EQ(s.spheres, 1u);
    EXPECT_EQ(s.disks, 1u);
    EXPECT_EQ(s.partialSpheres, 1u);
    EXPECT_EQ(s.cylinders, 2u);
    EXPECT_EQ(s.partialDisks, 1u);
    EXPECT_EQ(s.emitters, 1u);
    EXPECT_EQ(s.areaLights, 1u);
}

}  // namespace
}  // namespace lamina::render
