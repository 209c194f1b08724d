// Environment maps: importance sampling matches its density (chi-square, significance 0.01),
// lookups follow the documented mapping, and a constant image is a white furnace.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "lamina/core/chi_square_test.h"
#include "lamina/render/environment_map.h"
#include "render_helpers.h"

namespace lamina {
namespace {

std::vector<Rgb<float>> testImage(int w, int h) {
    std::vector<Rgb<float>> px(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // A smooth sky gradient, a bright sun, and a black band.
            float v = 0.2f + 0.8f * float(h - y) / float(h);
            if (std::abs(x - w / 3) < 3 && std::abs(y - h / 4) < 2) v = 50.0f;
            if (y > 3 * h / 4) v = 0.0f;
            px[std::size_t(y) * w + x] = Rgb<float>(v, 0.8f * v, 0.6f * v);
        }
    return px;
}

TEST(EnvironmentMap, SamplingMatchesItsDensity) {
    const render::EnvironmentMap map(64, 32, testImage(64, 32), {.rotateDegrees = 30.0});
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
    const render::EnvironmentMap map(64, 32, testImage(64, 32), {});
    // The zenith is brighter than the horizon; the black band below has density 0.
    EXPECT_GT(map.pdf(glm::normalize(Vec3<float>(0.1f, 1.0f, 0.0f))), map.pdf({1, 0, 0}));
    EXPECT_EQ(map.pdf({0, -1, 0}), 0.0f);
    EXPECT_EQ(map.lookup({0, -1, 0})[0], 0.0f);
}

TEST(EnvironmentMap, ConstantImageIsAWhiteFurnace) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("lamina-env-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "white.exr";
    {
        std::vector<float> data(16 * 8 * 3, 1.0f);
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open(file.string(), OIIO::ImageSpec(16, 8, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, data.data()));
        out->close();
    }
    const std::string scene = R"({
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
      "film": {"resolution": [16, 16]},
      "integrator": {"max_depth": 64},
      "materials": {"white": {"type": "lambert", "reflectance": 1}},
      "shapes": [{"type": "sphere", "radius": 1, "material": "white"}],
      "lights": [{"type": "environment", "file": ")" +
                              file.string() + R"(", "rotate": 45}]
    })";
    for (auto mode : {render::RenderModeKind::Rgb, render::RenderModeKind::Spectral}) {
        render::RenderOptions o;
        o.mode = mode;
        o.spp = 64;
        const auto r = render::renderScene(testing::sceneFromText(scene), o);
        for (int c = 0; c < 3; ++c) {
            const auto m = testing::imageMean(*r.film, c);
            EXPECT_LT(std::abs(m.mean - 1.0), 3.29 * m.standardError + 1e-4) << "channel " << c;
        }
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lamina
