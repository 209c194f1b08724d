// Environment maps: importance sampling matches its density (chi-square, significance 0.01),
// lookups follow the documented mapping, a constant image is a white furnace (in both
// mappings; environment_mapping_test.cpp tests the mappings and the transform), and a floor
// under a sky that shines only around the zenith has the closed form's radiance by every
// integrator and by BSDF sampling alone.
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

// A sky of radiance 10 within 45 degrees of the zenith and black below: a diffuse floor of
// reflectance 0.5 receives E = L pi sin^2(45 deg) and reflects 0.5 L / 2 = 2.5. Every escaping
// ray must look the sky up in its own direction: the path tracer once looked it up in the
// opposite one, so that BSDF-sampled rays saw the black nadir (1.98 with next-event estimation
// and MIS, 0 by BSDF sampling alone, where light tracing and BDPT gave 2.5).
TEST(EnvironmentMap, AFloorUnderAZenithSkyHasTheClosedFormsRadiance) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("lamina-zenith-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // 64 x 32 latitude-longitude: rows 0-7 are theta < 45 degrees exactly.
    std::vector<float> data(std::size_t(64 * 32 * 3), 0.0f);
    std::fill(data.begin(), data.begin() + 64 * 8 * 3, 10.0f);
    render::writeFloatExr(dir / "zenith.exr", 64, 32, {"R", "G", "B"}, data);
    const auto scene = [&](const std::string& integrator, bool nextEvent) {
        return testing::sceneFromText(R"({
          "camera": {"position": [0, 2, -3], "look_at": [0, 0, 0], "fov": 30},
          "film": {"resolution": [16, 16]},
          "integrator": {"type": ")" + integrator + R"(", "max_depth": 1)" +
                                      (integrator == "path" ? std::string(", \"next_event\": ") +
                                                                  (nextEvent ? "true" : "false")
                                                            : std::string()) +
                                      R"(},
          "materials": {"floor": {"type": "lambert", "reflectance": 0.5}},
          "shapes": [{"type": "rectangle", "material": "floor",
                      "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 3}]}],
          "lights": [{"type": "environment", "file": ")" +
                                      (dir / "zenith.exr").string() + R"("}]})");
    };
    const std::pair<std::string, bool> cases[] = {
        {"path", true}, {"path", false}, {"light", true}, {"bdpt", true}};
    for (const auto& [integrator, nextEvent] : cases) {
        render::RenderOptions o;
        o.spp = 256;
        const auto r = render::renderScene(scene(integrator, nextEvent), o);
        const auto m = testing::imageMean(*r.film, 0);
        EXPECT_NEAR(m.mean, 2.5, 4 * m.standardError + 1e-3)
            << integrator << (nextEvent ? "" : " without next-event estimation");
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lamina
