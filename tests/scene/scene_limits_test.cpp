// Numbers a scene may hold as JSON (finite doubles) but not render with: coordinates too large
// for float rays (Embree's ray.valid() aborted on 1e20), numbers that overflow or underflow
// float, emitters whose area float rounds away, a dispersion pole among the rendered
// wavelengths, a 180-degree field of view. Each is one error naming the JSON path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/core/error.h"
#include "render_helpers.h"

namespace lamina {
namespace {

using ::testing::HasSubstr;

const std::string kCamera = R"({"position": [0, 0, -4], "look_at": [0, 0, 0]})";

// A valid scene; `camera`, `shape`, `material`, the emitter's radiance and `lights` replace
// its parts.
std::string scene(const std::string& camera = kCamera,
                  const std::string& shape = R"({"type": "sphere", "radius": 1, "material": "m"})",
                  const std::string& material = R"({"type": "lambert"})",
                  const std::string& emission = "[1, 1, 1]", const std::string& lights = "[]") {
    return R"({"camera": )" + camera + R"(, "film": {"resolution": [8, 8]},
  "materials": {"m": )" +
           material + R"(},
  "shapes": [)" +
           shape + R"(,
    {"type": "rectangle", "material": "m", "transform": [{"translate": [0, 3, 0]}],
     "emission": {"radiance": )" +
           emission + R"(}}],
  "lights": )" +
           lights + "}";
}

std::string errorOf(const std::string& text) {
    try {
        (void)testing::sceneFromText(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(SceneLimits, TheValidSceneLoads) {
    EXPECT_EQ(errorOf(scene()), "(accepted)");
}

struct Case {
    const char* name;
    std::string text;
    const char* expected;  ///< the JSON path and the gist of the message
};

class Refused : public ::testing::TestWithParam<Case> {};

TEST_P(Refused, WithOneMessageNamingThePath) {
    const std::string message = errorOf(GetParam().text);
    EXPECT_THAT(message, HasSubstr(GetParam().expected));
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Class 1: geometry whose extent float rays cannot represent (1e20 aborted in Embree).
INSTANTIATE_TEST_SUITE_P(
    FarGeometry, Refused,
    ::testing::Values(
        Case{"CameraPosition", scene(R"({"position": [0, 0, -1e20], "look_at": [0, 0, 0]})"),
             "camera.position: (0, 0, -1e+20) is too far out"},
        Case{"CameraLookAt", scene(R"({"position": [0, 0, -4], "look_at": [1e20, 0, 0]})"),
             "camera.look_at: (1e+20, 0, 0)"},
        Case{"CameraMatrix", scene(R"({"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,-1e16, 0,0,0,1]})"),
             "camera.matrix: the position (0, 0, -1e+16)"},
        Case{"Aperture",
             scene(R"({"type": "thin_lens", "position": [0, 0, -4], "look_at": [0, 0, 0],
                     "aperture_radius": 1e20})"),
             "camera.aperture_radius: expected a number in [0, 1e+15]"},
        Case{"SphereCenter",
             scene(kCamera, R"({"type": "sphere", "center": [1e20, 0, 0], "material": "m"})"),
             "shapes[0].center: the sphere's bounding box corner"},
        Case{"SphereRadius",
             scene(kCamera, R"({"type": "sphere", "radius": 1e16, "material": "m"})"),
             "shapes[0].center: the sphere's bounding box corner"},
        Case{"Disk",
             scene(kCamera, R"({"type": "disk", "center": [0, -1e20, 0], "material": "m"})"),
             "shapes[0].center: the disk's"},
        Case{"InlineMesh",
             scene(kCamera,
                   R"({"type": "mesh", "material": "m", "positions": [[0,0,0],[1e20,0,0],[0,1,0]],
                          "faces": [[0, 1, 2]]})"),
             // mesh positions are floats
             "shapes[0].positions: vertex 1 at (1.00000002e+20, 0, 0)"},
        Case{"MeshTransform",
             scene(kCamera,
                   R"({"type": "rectangle", "material": "m", "transform": [{"scale": 1e20}]})"),
             "shapes[0].transform: vertex 0 at"},
        Case{"PointLight",
             scene(kCamera, R"({"type": "sphere", "material": "m"})", R"({"type": "lambert"})",
                   "[1, 1, 1]", R"([{"type": "point", "intensity": 1, "position": [0, 1e20, 0]}])"),
             "lights[0].position: (0, 1e+20, 0)"},
        Case{
            "SpotTarget",
            scene(
                kCamera, R"({"type": "sphere", "material": "m"})", R"({"type": "lambert"})",
                "[1, 1, 1]",
                R"([{"type": "spot", "intensity": 1, "position": [0, 1, 0], "look_at": [0, -1e20, 0]}])"),
            "lights[0].look_at: (0, -1e+20, 0)"}),
    [](const auto& paramInfo) { return std::string(paramInfo.param.name); });

// Class 3: numbers finite in double but not in float, or meaningless for a scene.
INSTANTIATE_TEST_SUITE_P(
    FloatNumbers, Refused,
    ::testing::Values(
        Case{"RadianceOverflow",
             scene(kCamera, R"({"type": "sphere", "material": "m"})", R"({"type": "lambert"})",
                   "1e39"),
             "shapes[1].emission.radiance: expected a number >= 0 representable in float"},
        Case{"ScaleOverflow",
             scene(kCamera, R"({"type": "sphere", "material": "m"})", R"({"type": "lambert"})",
                   R"({"illuminant": "D65", "scale": 1e39})"),
             "shapes[1].emission.radiance.scale: expected a number >= 0 representable in float"},
        Case{"ScaledSpectrumOverflow",
             scene(kCamera, R"({"type": "sphere", "material": "m"})", R"({"type": "lambert"})",
                   R"({"spectrum": [[400, 1e30], [700, 1e30]], "scale": 1e30})"),
             "shapes[1].emission.radiance: the emission overflows float"},
        Case{"TransformScale",
             scene(kCamera,
                   R"({"type": "sphere", "material": "m", "transform": [{"scale": 1e39}]})"),
             "shapes[0].transform[0].scale: expected a finite number representable in float"},
        Case{"Underflow", scene(kCamera, R"({"type": "sphere", "radius": 1e-40, "material": "m"})"),
             "shapes[0].radius: expected a number > 0 representable in float"},
        Case{"ZeroAreaSphereEmitter",
             scene(kCamera, R"({"type": "sphere", "radius": 1e-30, "material": "m",
                          "emission": {"radiance": 1}})"),
             "shapes[0].emission: the emitting shape has zero area in float"},
        Case{"ZeroAreaTriangleEmitter",
             scene(kCamera, R"({"type": "mesh", "material": "m", "emission": {"radiance": 1},
                          "positions": [[0,0,0],[1e-20,0,0],[0,1e-20,0]], "faces": [[0, 1, 2]]})"),
             "shapes[0].emission: the emitting shape has zero area in float"},
        Case{"SellmeierPole",
             scene(kCamera, R"({"type": "sphere", "material": "m"})",
                   R"({"type": "dielectric", "ior": {"sellmeier": {"b": [1.0], "c": [0.25]}}})"),
             "materials.m.ior.sellmeier.c[0]: puts a pole of the formula at 500 nm"},
        Case{"CauchyNegative",
             scene(kCamera, R"({"type": "sphere", "material": "m"})",
                   R"({"type": "dielectric", "ior": {"cauchy": [1.0, -1.0]}})"),
             "materials.m.ior: the formula gives n = "},
        Case{"Fov180", scene(R"({"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 180})"),
             "camera.fov: expected a number in (0, 180), got 180"},
        Case{"FocalLength180",
             scene(R"({"position": [0, 0, -4], "look_at": [0, 0, 0], "focal_length": 1e-30})"),
             "camera.focal_length: is too short for the sensor"}),
    [](const auto& paramInfo) { return std::string(paramInfo.param.name); });

// The limits are not tighter than they need to be.
TEST(SceneLimits, LargeAndSmallButRepresentableScenesLoad) {
    EXPECT_EQ(errorOf(scene(R"({"position": [0, 0, -1e14], "look_at": [0, 0, 0]})",
                            R"({"type": "sphere", "radius": 1e13, "material": "m"})")),
              "(accepted)");
    EXPECT_EQ(errorOf(scene(kCamera, R"({"type": "sphere", "radius": 1e-18, "material": "m",
                                     "emission": {"radiance": 1}})")),
              "(accepted)");
    EXPECT_EQ(errorOf(scene(R"({"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 179.9})")),
              "(accepted)");
    EXPECT_EQ(errorOf(scene(
                  kCamera, R"({"type": "sphere", "material": "m"})",
                  R"({"type": "dielectric", "ior": {"sellmeier": {"b": [1.0], "c": [0.01]}}})")),
              "(accepted)");
}

}  // namespace
}  // namespace lamina
