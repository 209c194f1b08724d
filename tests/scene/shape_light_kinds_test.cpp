// Shapes and lights as one variant of kinds each (shape_description.h, light_description.h):
// the loader orders a scene's shapes by kind, which is the order of their Embree geometry ids
// and of the emitters' lights, and every kind of light reads into its own alternative.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lamina/geometry/geometry.h"
#include "lamina/lights/lights.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

// Seven emitters in a row along x, one every 3 units, in mixed order of kinds: a disk, a mesh,
// a sphere, a rectangle, a disk, a sphere, a clipped disk (a quadric, read first). Rays along +z
// from z = -5 hit the one at x = 3 k.
constexpr const char* kMixedShapes = R"({
  "materials": {"m": {"type": "lambert", "reflectance": 0.5}},
  "objects": {"o": [
    {"type": "disk", "name": "od", "material": "m"},
    {"type": "sphere", "name": "os", "material": "m"},
    {"type": "mesh", "name": "om", "material": "m",
     "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]]}
  ]},
  "shapes": [
    {"type": "disk", "name": "q1", "material": "m", "radius": 0.5, "phi_max": 300,
     "flip_normals": true, "emission": {"radiance": 1}, "transform": [{"translate": [18, 0, 0]}]},
    {"type": "disk", "name": "d1", "material": "m", "center": [0, 0, 0], "normal": [0, 0, -1],
     "radius": 0.5, "emission": {"radiance": 1}},
    {"type": "mesh", "name": "m1", "material": "m", "emission": {"radiance": 1},
     "positions": [[2.5, -0.5, 0], [3.5, -0.5, 0], [3, 0.5, 0]], "faces": [[0, 2, 1]]},
    {"type": "sphere", "name": "s1", "material": "m", "center": [6, 0, 0], "radius": 0.5,
     "emission": {"radiance": 1}},
    {"type": "rectangle", "name": "r1", "material": "m", "emission": {"radiance": 1},
     "transform": [{"scale": 0.5}, {"translate": [9, 0, 0]}]},
    {"type": "disk", "name": "d2", "material": "m", "center": [12, 0, 0], "normal": [0, 0, -1],
     "radius": 0.5, "emission": {"radiance": 1}},
    {"type": "sphere", "name": "s2", "material": "m", "center": [15, 0, 0], "radius": 0.5,
     "emission": {"radiance": 1}},
    {"type": "instance", "object": "o", "transform": [{"translate": [0, 10, 0]}]}
  ]
})";

std::vector<std::string> namesOf(const std::vector<ShapeDesc>& shapes) {
    std::vector<std::string> names;
    for (const ShapeDesc& shape : shapes)
        names.push_back(surface(shape).name);
    return names;
}

TEST(ShapeKinds, MixedKindsAreOrderedMeshesSpheresDisksQuadricsAsGeometryIdsAndLights) {
    const SceneDesc scene = testing::sceneFromText(kMixedShapes);
    // Every mesh, then every sphere, then every disk, then every quadric, each kind in the
    // file's order.
    EXPECT_THAT(namesOf(scene.shapes),
                ::testing::ElementsAre("m1", "r1", "s1", "s2", "d1", "d2", "q1"));
    EXPECT_TRUE(std::holds_alternative<MeshDesc>(scene.shapes[1]));
    EXPECT_TRUE(std::holds_alternative<SphereDesc>(scene.shapes[2]));
    EXPECT_TRUE(std::holds_alternative<DiskDesc>(scene.shapes[5]));
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_THAT(namesOf(scene.objects[0].shapes), ::testing::ElementsAre("om", "os", "od"));

    // A shape's index is its Embree geometry id, and the object's shapes follow the scene's.
    const Geometry geometry(scene);
    ASSERT_EQ(geometry.shapes().size(), 10u);
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        EXPECT_EQ(geometry.shapes()[i].desc, &scene.shapes[i]) << i;
        EXPECT_EQ(geometry.shapes()[i].object, -1) << i;
    }
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(geometry.shapes()[7 + i].desc, &scene.objects[0].shapes[i]) << i;

    // One light per shape here (a one-triangle mesh, a rectangle, spheres, disks and a
    // quadric), made in the shapes' order: the hit shape's light is the light of the same index.
    const LightSet lights(scene, geometry, LightSelection::Uniform);
    ASSERT_EQ(lights.size(), 7u);
    const std::vector<std::string> inFile{"d1", "m1", "s1", "r1", "d2", "s2", "q1"};
    for (std::size_t k = 0; k < inFile.size(); ++k) {
        const auto hit = geometry.intersect(Vec3f(3.0f * float(k), 0, -5), Vec3f(0, 0, 1));
        ASSERT_TRUE(hit) << inFile[k];
        EXPECT_EQ(surface(scene.shapes[std::size_t(hit->shape)]).name, inFile[k]);
        EXPECT_EQ(lights.lightAt(*hit), hit->shape) << inFile[k];
    }
}

TEST(LightKinds, EachKindReadsIntoItsOwnAlternative) {
    const std::string sky = testing::sourceFile("tests/data/interchange/mitsuba/sky.exr").string();
    const SceneDesc scene = testing::sceneFromText(R"({"lights": [
      {"type": "spot", "position": [0, 2, 0], "look_at": [0, 0, 0], "intensity": [1, 2, 3],
       "cone_angle": 40, "falloff_start": 10},
      {"position": [1, 2, 3], "intensity": {"blackbody": 3000, "scale": 2}},
      {"type": "directional", "direction": [0, 0, -2], "irradiance": 4},
      {"type": "environment", "radiance": 0.5},
      {"type": "environment", "file": ")" + sky +
                                                   R"(", "scale": 3, "mapping":
       "equal_area_octahedral", "rotate": 90}
    ]})");
    ASSERT_EQ(scene.lights.size(), 5u);
    std::vector<std::string> kinds;
    for (const LightDesc& l : scene.lights)
        kinds.emplace_back(kLightKindNames.name(lightKind(l)));
    EXPECT_THAT(kinds, ::testing::ElementsAre("spot", "point", "directional", "environment",
                                              "environment"));

    const auto& spot = std::get<SpotLightDesc>(scene.lights[0]);
    EXPECT_EQ(spot.position, Vec3d(0, 2, 0));
    EXPECT_EQ(spot.direction, Vec3d(0, -1, 0));
    EXPECT_EQ(spot.coneAngle, 40);
    EXPECT_EQ(spot.falloffStart, 10);
    EXPECT_EQ(spot.intensity, Rgb<double>(1, 2, 3));
    EXPECT_FALSE(spot.spectrum);

    // Without a type: a point light.
    const auto& point = std::get<PointLightDesc>(scene.lights[1]);
    EXPECT_EQ(point.position, Vec3d(1, 2, 3));
    ASSERT_TRUE(point.spectrum);
    EXPECT_EQ(point.intensity, point.spectrum->rgb());
    EXPECT_EQ(&lightIntensity(scene.lights[1]), static_cast<const LightIntensityDesc*>(&point));

    const auto& directional = std::get<DirectionalLightDesc>(scene.lights[2]);
    EXPECT_EQ(directional.direction, Vec3d(0, 0, -1));
    EXPECT_EQ(directional.intensity, Rgb<double>(4));

    const auto& constant = std::get<EnvironmentLightDesc>(scene.lights[3]);
    EXPECT_TRUE(constant.file.empty());
    EXPECT_EQ(constant.intensity, Rgb<double>(0.5));

    const auto& image = std::get<EnvironmentLightDesc>(scene.lights[4]);
    EXPECT_EQ(image.file, std::filesystem::path(sky));
    EXPECT_EQ(image.intensity, Rgb<double>(3));
    EXPECT_EQ(image.mapping, EnvironmentMapping::EqualAreaOctahedral);
    EXPECT_EQ(image.rotation, 90);
    EXPECT_EQ(image.orientation, Mat3<double>(1.0));
}

}  // namespace
}  // namespace lamina::render
