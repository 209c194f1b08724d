// Environment maps: importance sampling matches its density (chi-square, significance 0.01),
// lookups follow the documented mapping, and a constant image is a white furnace (in both
// mappings; environment_mapping_test.cpp tests the mappings and the transform).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "lamina/core/chi_square_test.h"
#include "lamina/lights/environment_map.h"
#include "lamina/output/image_output.h"
#include "render_helpers.h"

namespace lamina {
namespace {

TEST(EnvironmentMap, SamplingMatchesItsDensity) {
    const render::EnvironmentMap map(64, 32, testing::skyTestImage(64, 32),
                                     {.rotateDegrees = 30.0});
    ChiSquareConfig config;
    config.sampleCount = 500000;
    config.significance = 0.01;
    const auto r = runChiSquareTest(
        config,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            float pdf;
            const Vec3<float> w = map.sample(Vec2<float>(rng.nextFloat(), rng.nextFloat()), pdf);
            if (!(pdf > 0)) return std::nullopt;
            // The test's grid is (phi, cos theta) about z; swap y and z so that its poles are
            // the map's.
            return Vec3d(w.x, w.z, w.y);
        },
        [&](const Vec3d& w) {
            return double(map.pdf(Vec3<float>(float(w.x), float(w.z), float(w.y))));
        });
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(EnvironmentMap, DensityFollowsBrightness) {
    const render::EnvironmentMap map(64, 32, testing::skyTestImage(64, 32), {});
    // The zenith is brighter than the horizon; the black band below has density 0.
    EXPECT_GT(map.pdf(glm::normalize(Vec3<float>(0.1f, 1.0f, 0.0f))), map.pdf({1, 0, 0}));
    EXPECT_EQ(map.pdf({0, -1, 0}), 0.0f);
    EXPECT_EQ(map.lookup({0, -1, 0})[0], 0.0f);
}

TEST(EnvironmentMap, ConstantImageIsAWhiteFurnace) {
    // In either mapping, turned or not: a 16 x 8 latitude-longitude image and an 8 x 8
    // equal-area octahedral one (under a mirror and a rotation).
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("lamina-env-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const auto write = [&](const std::string& name, int w, int h) {
        const fs::path file = dir / name;
        std::vector<float> data(std::size_t(w * h * 3), 1.0f);
        render::writeFloatExr(file, w, h, {"R", "G", "B"}, data);
        return file.string();
    };
    const std::string lights[] = {
        R"({"type": "environment", "file": ")" + write("white.exr", 16, 8) + R"(", "rotate": 45})",
        R"({"type": "environment", "file": ")" + write("square.exr", 8, 8) +
            R"(", "mapping": "equal_area_octahedral", "transform": [{"scale": [-1, 1, 1]},
               {"rotate": {"axis": [0, 0, 1], "angle": 30}}]})"};
    for (const std::string& light : lights) {
        const std::string scene = R"({
          "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
          "film": {"resolution": [16, 16]},
          "integrator": {"max_depth": 64},
          "materials": {"white": {"type": "lambert", "reflectance": 1}},
          "shapes": [{"type": "sphere", "radius": 1, "material": "white"}],
          "lights": [)" + light + "]}";
        for (auto mode : {render::RenderModeKind::Rgb, render::RenderModeKind::Spectral}) {
            render::RenderOptions o;
            o.mode = mode;
            o.spp = 64;
            const auto r = render::renderScene(testing::sceneFromText(scene), o);
            for (int c = 0; c < 3; ++c) {
                const auto m = testing::imageMean(*r.film, c);
                EXPECT_LT(std::abs(m.mean - 1.0), 3.29 * m.standardError + 1e-4)
                    << light << ", channel " << c;
            }
        }
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lamina
