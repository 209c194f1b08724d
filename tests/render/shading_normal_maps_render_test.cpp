// A bump or normal map changes the shading of a render as a turned normal must: a Lambert floor
// (albedo 1/2) lit by a point light of intensity I straight above it at height h and seen
// straight down, direct lighting only, has the radiance rho / pi * I / h^2 * cos t, t the angle
// between the mapped normal and the light. The normal map's colour (1/2 + sin t / 2, 1/2,
// 1/2 + cos t / 2) turns it by t; a height a u on the floor of 10 units across (dp/du = 10),
// by atan(a / 10).
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/image/image_io.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

class ShadingNormalMapRender : public testing::ScratchDirectoryTest {
  protected:
    // The floor's centre pixel with the material keys `maps` (and the scene's `textures`).
    double centre(const std::string& textures, const std::string& maps) const {
        const SceneDesc scene = testing::sceneFromText(R"({
          "camera": {"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 0.5},
          "film": {"resolution": [4, 4]},
          "integrator": {"max_depth": 1},
          "textures": )" + textures + R"(,
          "materials": {"floor": {"type": "lambert", "reflectance": 0.5)" +
                                                       maps + R"(}},
          "shapes": [{"type": "rectangle", "material": "floor",
                      "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 5}]}],
          "lights": [{"type": "point", "position": [0, 2, 0], "intensity": 10}]})");
        RenderOptions o;
        o.spp = 4;
        const auto r = renderScene(scene, o);
        return r.film->pixel(2, 2)[1];
    }
    static constexpr double kFlat = 0.5 / kPi<double> * 10.0 / 4.0;
};

TEST_F(ShadingNormalMapRender, ANormalMapTiltedByTDimsTheFloorByCosT) {
    EXPECT_NEAR(centre("{}", ""), kFlat, 1e-3 * kFlat);
    for (const double degrees : {20.0, 45.0, 70.0}) {
        const double t = radians(degrees);
        const std::string colour = "[" + std::to_string(0.5 + 0.5 * std::sin(t)) + ", 0.5, " +
                                   std::to_string(0.5 + 0.5 * std::cos(t)) + "]";
        const double got =
            centre(R"({"n": {"type": "checkerboard", "a": )" + colour + ", \"b\": " + colour + "}}",
                   R"(, "normal_map": {"texture": "n"})");
        EXPECT_NEAR(got, kFlat * std::cos(t), 1e-3 * kFlat) << degrees << " degrees";
    }
}

TEST_F(ShadingNormalMapRender, ABumpOfSlopeADimsTheFloorByTheCosineOfItsTilt) {
    // h(u) = u between the first and last texel centres of 64 texels, times a.
    std::vector<float> ramp;
    for (int i = 0; i < 64; ++i)
        ramp.insert(ramp.end(), 3, (float(i) + 0.5f) / 64);
    writeFloatExr(dir_ / "ramp.exr", 64, 1, {"R", "G", "B"}, ramp);
    for (const double a : {3.0, 10.0}) {
        const double got =
            centre(R"({"ramp": {"type": "image", "file": ")" + (dir_ / "ramp.exr").string() + R"("},
                                      "bumps": {"type": "scale", "texture": "ramp", "scale": )" +
                       std::to_string(a) + "}}",
                   R"(, "displacement": {"texture": "bumps"})");
        EXPECT_NEAR(got, kFlat * std::cos(std::atan(a / 10.0)), 1e-3 * kFlat) << "a = " << a;
    }
}

}  // namespace
}  // namespace lamina::render
