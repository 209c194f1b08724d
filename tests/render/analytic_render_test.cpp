// Renders with known answers: the white furnace, a closed emitting sphere and a closed can of
// pbrt-v4's quadrics. Each test
// checks the image mean with a z-test at significance 0.001 (|z| < 3.29), using the
// per-pixel variance estimates of the film as the standard error.
#include <gtest/gtest.h>

#include <filesystem>

#include "lamina/geometry/geometry.h"
#include "render_helpers.h"
#include "source_files.h"

namespace lamina {
namespace {

using testing::imageMean;
using testing::sceneFromText;

constexpr double kZ = 3.29;  // two-sided significance 0.001

render::RenderResult renderText(const std::string& json, render::RenderModeKind mode, int spp) {
    render::RenderOptions o;
    o.mode = mode;
    o.spp = spp;
    return render::renderScene(sceneFromText(json), o);
}

const char* kFurnace = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
  "film": {"resolution": [24, 24]},
  "integrator": {"max_depth": 64},
  "materials": {"white": {"type": "lambert", "reflectance": 1}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}],
  "lights": [{"type": "environment", "radiance": 1}]
})";

class AnalyticRender : public ::testing::TestWithParam<render::RenderModeKind> {};

TEST_P(AnalyticRender, WhiteFurnaceIsOneEverywhere) {
    const auto r = renderText(kFurnace, GetParam(), 64);
    for (int c = 0; c < 3; ++c) {
        const auto m = imageMean(*r.film, c);
        EXPECT_LT(std::abs(m.mean - 1.0), kZ * m.standardError + 1e-4)
            << "channel " << c << " mean " << m.mean << " se " << m.standardError;
    }
    // Every pixel, not only the mean: within 5 of its own standard errors (or 1e-3).
    int outliers = 0;
    for (int y = 0; y < r.film->height(); ++y)
        for (int x = 0; x < r.film->width(); ++x) {
            const double v = r.film->pixel(x, y)[1];
            const double se = std::sqrt(r.film->varianceOfMean(x, y));
            outliers += std::abs(v - 1.0) > 5 * se + 1e-3;
        }
    EXPECT_EQ(outliers, 0);
    EXPECT_EQ(r.film->rejectedSamples(), 0u);
}

TEST_P(AnalyticRender, ClosedEmittingSphereGivesLeOverOneMinusRho) {
    // Inside a sphere that emits Le = 1 and reflects diffusely with albedo 0.5, the radiance
    // is Le (1 + rho + rho^2 + ...) = Le / (1 - rho) = 2 everywhere (truncated at depth 64).
    const char* scene = R"({
      "camera": {"position": [0, 0, 0], "look_at": [0, 0, 1], "fov": 60},
      "film": {"resolution": [16, 16]},
      "integrator": {"max_depth": 64, "rr_depth": 64},
      "materials": {"m": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [{"type": "sphere", "radius": 3, "flip_normals": true, "material": "m",
                  "emission": {"radiance": 1}}]
    })";
    const auto r = renderText(scene, GetParam(), 64);
    for (int c = 0; c < 3; ++c) {
        const auto m = imageMean(*r.film, c);
        EXPECT_LT(std::abs(m.mean - 2.0), kZ * m.standardError + 1e-4)
            << "channel " << c << " mean " << m.mean << " se " << m.standardError;
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, AnalyticRender,
                         ::testing::Values(render::RenderModeKind::Rgb,
                                           render::RenderModeKind::Spectral,
                                           render::RenderModeKind::Polarised),
                         [](const auto& paramInfo) {
                             return std::string(render::kRenderModeNames.name(paramInfo.param));
                         });

// A closed can of pbrt-v4's quadrics facing inwards: a cylinder (radius 1, z in [-1, 1]), a
// lid of two half-disks (phi_max 180, the second turned by 180 degrees) and a bottom of an
// annulus (inner radius 0.5) around a whole disk, all emitting Le = 1 and reflecting
// diffusely with albedo 0.5. Inside, the radiance is Le / (1 - rho) = 2 everywhere (truncated
// at depth 24: 2 (1 - 0.5^25), 6e-8 short), by every integrator: each quadric's intersection and clipping, its emission
// and its sampling by area (next-event estimation and MIS, particles, BDPT's connections)
// must be right for that.
const char* kClosedQuadricCan = R"({
  "camera": {"position": [0, 0, -0.2], "look_at": [0.3, 0.2, 1], "fov": 80},
  "film": {"resolution": [12, 12]},
  "integrator": {"max_depth": 24, "rr_depth": 24},
  "materials": {"m": {"type": "lambert", "reflectance": 0.5}},
  "shapes": [
    {"type": "cylinder", "flip_normals": true, "material": "m", "emission": {"radiance": 1},
     "transform": [{"rotate": {"axis": [0, 0, 1], "angle": 20}}]},
    {"type": "disk", "phi_max": 180, "flip_normals": true, "material": "m",
     "emission": {"radiance": 1}, "transform": [{"translate": [0, 0, 1]}]},
    {"type": "disk", "phi_max": 180, "flip_normals": true, "material": "m",
     "emission": {"radiance": 1},
     "transform": [{"rotate": {"axis": [0, 0, 1], "angle": 180}}, {"translate": [0, 0, 1]}]},
    {"type": "disk", "inner_radius": 0.5, "material": "m", "emission": {"radiance": 1},
     "transform": [{"translate": [0, 0, -1]}]},
    {"type": "disk", "radius": 0.5, "material": "m", "emission": {"radiance": 1},
     "center": [0, 0, -1]}
  ]
})";

class ClosedQuadricCan : public ::testing::TestWithParam<render::IntegratorKind> {};

TEST_P(ClosedQuadricCan, RadianceInsideIsLeOverOneMinusRho) {
    render::RenderOptions o;
    o.integrator = GetParam();
    o.spp = GetParam() == render::IntegratorKind::Light ? 256 : 64;
    const auto r = render::renderScene(sceneFromText(kClosedQuadricCan), o);
    for (int c = 0; c < 3; ++c) {
        const auto m = imageMean(*r.film, c);
        EXPECT_LT(std::abs(m.mean - 2.0), kZ * m.standardError + 1e-4)
            << "channel " << c << " mean " << m.mean << " se " << m.standardError;
    }
    EXPECT_EQ(r.film->rejectedSamples(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Integrators, ClosedQuadricCan,
                         ::testing::Values(render::IntegratorKind::Path,
                                           render::IntegratorKind::Light,
                                           render::IntegratorKind::Bdpt),
                         [](const auto& paramInfo) {
                             return std::string(render::kIntegratorNames.name(paramInfo.param));
                         });

// Renders a scene in both modes and z-tests the image mean of each channel (|z| < 3.29).
void expectModesAgree(const char* scene, int spp) {
    const auto rgb = renderText(scene, render::RenderModeKind::Rgb, spp);
    const auto spectral = renderText(scene, render::RenderModeKind::Spectral, spp);
    for (int c = 0; c < 3; ++c) {
        const auto a = imageMean(*rgb.film, c), b = imageMean(*spectral.film, c);
        const double se = std::hypot(a.standardError, b.standardError);
        EXPECT_LT(std::abs(a.mean - b.mean), kZ * se)
            << "channel " << c << ": rgb " << a.mean << " spectral " << b.mean << " se " << se;
    }
}

TEST(ModesAgree, GreyMaterialsUnderWhiteLightRenderTheSameInRgbAndSpectral) {
    // Grey reflectances and white (1, 1, 1) light mean the same spectrum-free thing in both
    // modes: the images agree within statistical error (z-test on the mean of each channel
    // and of quarters of the image, |z| < 3.29 each).
    const char* scene = R"({
      "camera": {"position": [0, 1, -3.5], "look_at": [0, 1, 0], "fov": 45},
      "film": {"resolution": [32, 32]},
      "materials": {"grey": {"type": "lambert", "reflectance": 0.6},
                    "dark": {"type": "oren_nayar", "reflectance": 0.25, "roughness": 0.7},
                    "metal": {"type": "conductor", "eta": 1.5, "k": 3.0, "roughness": 0.4}},
      "shapes": [
        {"type": "rectangle", "material": "grey",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 3}]},
        {"type": "sphere", "center": [-0.6, 0.5, 0], "radius": 0.5, "material": "metal"},
        {"type": "sphere", "center": [0.6, 0.5, 0.3], "radius": 0.5, "material": "dark"},
        {"type": "rectangle", "material": "grey", "emission": {"radiance": 4},
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"scale": 0.5},
                       {"translate": [0, 2.5, 0]}]}
      ],
      "lights": [{"type": "environment", "radiance": 0.2}]
    })";
    expectModesAgree(scene, 128);
}

TEST(ModesAgree, SpectralEmittersUnderGreyMaterials) {
    // A black body and a CIE illuminant as emitters: RGB mode uses their colour (the CMF
    // reduction), spectral mode the spectra; with grey materials both must agree.
    const char* scene = R"({
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
      "film": {"resolution": [24, 24]},
      "materials": {"grey": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [
        {"type": "sphere", "radius": 1, "material": "grey"},
        {"type": "sphere", "center": [2, 2, -1], "radius": 0.5, "material": "grey",
         "emission": {"radiance": {"illuminant": "A", "scale": 4}}}
      ],
      "lights": [{"type": "environment", "radiance": {"blackbody": 6000, "scale": 0.5}}]
    })";
    expectModesAgree(scene, 128);
}

TEST(DeltaLights, PointAndSpotLightsGiveTheInverseSquareLaw) {
    // A Lambert floor (albedo 0.5) under a light of intensity 10 at height 2, seen straight
    // down with a narrow camera, direct lighting only: L = rho / pi * I / h^2.
    for (const std::string light :
         {R"({"type": "point", "position": [0, 2, 0], "intensity": 10})",
          R"({"type": "spot", "position": [0, 2, 0], "look_at": [0, 0, 0], "intensity": 10,
              "cone_angle": 30, "falloff_start": 20})"}) {
        const std::string scene = R"({
          "camera": {"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 0.5},
          "film": {"resolution": [4, 4]},
          "integrator": {"max_depth": 1},
          "materials": {"floor": {"type": "lambert", "reflectance": 0.5}},
          "shapes": [{"type": "rectangle", "material": "floor",
                      "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 5}]}],
          "lights": [)" + light + "]}";
        const auto r = renderText(scene, render::RenderModeKind::Rgb, 4);
        const double expected = 0.5 / kPi<double> * 10.0 / 4.0;
        EXPECT_NEAR(r.film->pixel(2, 2)[1], expected, 1e-3 * expected) << light;
    }
    // Outside the spot's cone there is no light.
    const auto dark = renderText(R"({
      "camera": {"position": [3, 1, 0], "look_at": [3, 0, 0], "up": [0, 0, 1], "fov": 0.5},
      "film": {"resolution": [4, 4]}, "integrator": {"max_depth": 1},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [{"type": "rectangle", "material": "floor",
                  "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 5}]}],
      "lights": [{"type": "spot", "position": [0, 2, 0], "look_at": [0, 0, 0], "intensity": 10,
                  "cone_angle": 30}]})",
                                 render::RenderModeKind::Rgb, 4);
    EXPECT_EQ(dark.film->pixel(2, 2)[1], 0.0);
}

TEST(DiskLight, IrradianceBelowTheCentreIsAnalytic) {
    // A disk of radius R and radiance L at height h above a Lambert floor of albedo rho: under
    // its centre E = pi L R^2 / (h^2 + R^2), so the floor's radiance is rho L R^2 / (h^2 + R^2).
    const char* scene = R"({
      "camera": {"position": [0, 0.5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 0.5},
      "film": {"resolution": [4, 4]},
      "integrator": {"max_depth": 1},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.5},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [{"type": "rectangle", "material": "floor",
                  "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 5}]},
                 {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1.5,
                  "material": "lamp", "emission": {"radiance": 3}}]
    })";
    const auto r = renderText(scene, render::RenderModeKind::Rgb, 1024);
    const double expected = 0.5 * 3 * 1.5 * 1.5 / (4 + 1.5 * 1.5);
    const auto m = imageMean(*r.film, 1);
    EXPECT_LT(std::abs(m.mean - expected), kZ * m.standardError + 1e-4 * expected)
        << m.mean << " vs " << expected;
    // The disk itself is round: rays just inside its radius hit it, just outside miss.
    const auto desc = testing::sceneFromText(scene);
    const render::Geometry g(desc);
    for (double rho : {1.49, 1.51}) {
        const auto hit = g.intersect(Vec3f(float(rho), 3, 0), Vec3f(0, -1, 0));
        ASSERT_TRUE(hit);
        EXPECT_EQ(
            std::holds_alternative<render::DiskDesc>(*g.shapes()[std::size_t(hit->shape)].desc),
            rho < 1.5);
    }
}

TEST(Camera, AMatrixEqualsTheLookAtItEncodes) {
    // The Cornell box camera as a camera-to-world matrix (at (278, 273, -800), looking along
    // +z, up +y) renders the same image as its look_at form.
    auto scene = render::loadScene(testing::sharedCornellBox());
    render::RenderOptions o;
    o.spp = 2;
    o.resolution = std::make_pair(16, 16);
    const auto a = render::renderScene(scene, o);
    const JsonSource source{"<matrix>", "."};
    const Json j = parseJsonText(
        R"({"camera": {"matrix": [1, 0, 0, 278, 0, 1, 0, 273, 0, 0, 1, -800, 0, 0, 0, 1],
        "fov": 39.3077}, "shapes": [], "lights": [{"type": "point", "position": [0, 0, 0], "intensity": 1}]})",
        source);
    scene.camera = render::parseScene(j.dump(), source).camera;
    const auto b = render::renderScene(scene, o);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            ASSERT_EQ(a.film->pixel(x, y)[0], b.film->pixel(x, y)[0]);
}

TEST(Progressive, InterruptionFinishesThePassInFlightAndMarksThePartialImage) {
    auto scene = render::loadScene(testing::sharedCornellBox());
    render::RenderOptions o;
    o.spp = 1024;
    o.resolution = std::make_pair(16, 16);
    auto& flag = render::renderInterruptFlag();
    const auto r = render::renderScene(scene, o, [&](const render::RenderProgress& p) {
        if (p.passesDone == 3) flag.store(true);  // as Ctrl-C would, between passes
    });
    flag.store(false);
    EXPECT_TRUE(r.partial);
    EXPECT_EQ(r.spp,
              4);  // passes of 1, 1 and 2 spp; the flag raised after the third stops the loop
    EXPECT_GT(r.film->pixel(8, 8)[1], 0.0);
}

// A time budget is used up in whole passes that end close to it (pass_schedule.h: within half
// a sample per pixel, which is microseconds here; the tolerance is for a loaded machine).
TEST(Progressive, TimeLimitRendersWholePassesUntilTheTimeIsUsed) {
    auto scene = render::loadScene(testing::sharedCornellBox());
    render::RenderOptions o;
    o.seconds = 0.3;
    o.resolution = std::make_pair(16, 16);
    const auto r = render::renderScene(scene, o);
    EXPECT_FALSE(r.partial);
    EXPECT_NEAR(r.seconds, 0.3, 0.1);
    EXPECT_GT(r.spp, 1);
}

TEST(Determinism, SameImageWithOneAndTwoThreads) {
    auto scene = render::loadScene(testing::sharedCornellBox());
    render::RenderOptions o;
    o.spp = 4;
    o.resolution = std::make_pair(48, 48);
    o.threads = 1;
    const auto a = render::renderScene(scene, o);
    o.threads = 2;
    const auto b = render::renderScene(scene, o);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(a.film->pixel(x, y)[c], b.film->pixel(x, y)[c]) << x << "," << y;
}

}  // namespace
}  // namespace lamina

namespace lamina {
namespace {

// Every example scene loads and renders (tiny, 1 spp) in both modes without rejected
// samples: the scenes in the repository stay valid as the format evolves.
TEST(ExampleScenes, LoadAndRenderInBothModes) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(testing::sourceFile("scenes"))) {
        if (entry.path().extension() != ".json") continue;
        const auto scene = render::loadScene(entry.path());
        for (auto mode : {render::RenderModeKind::Rgb, render::RenderModeKind::Spectral}) {
            render::RenderOptions o;
            o.mode = mode;
            o.spp = 1;
            o.resolution = std::make_pair(12, 8);
            const auto r = render::renderScene(scene, o);
            EXPECT_EQ(r.film->rejectedSamples(), 0u) << entry.path();
        }
        ++scenes;
    }
    EXPECT_GE(scenes, 6);
}

}  // namespace
}  // namespace lamina

namespace lamina {
namespace {

// At equal spp the Owen-scrambled Sobol sampler's error on the Cornell box is below the
// independent sampler's (mean squared error against a 1024-spp reference, summed over three
// seeds so one lucky seed cannot decide), and so is sobol-global's (its film positions one
// global net, the rest Sobol's).
TEST(SamplerQuality, SobolBeatsIndependentOnTheCornellBox) {
    const auto scene = render::loadScene(testing::sharedCornellBox());
    render::RenderOptions o;
    o.resolution = std::make_pair(48, 48);
    o.spp = 1024;
    o.seed = 1000;
    const auto reference = render::renderScene(scene, o);
    const render::SamplerKind kinds[3] = {render::SamplerKind::Sobol,
                                          render::SamplerKind::Independent,
                                          render::SamplerKind::SobolGlobal};
    double mse[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        for (std::uint64_t seed : {1, 2, 3}) {
            o.spp = 16;
            o.seed = seed;
            o.sampler = kinds[k];
            const auto r = render::renderScene(scene, o);
            for (int y = 0; y < 48; ++y)
                for (int x = 0; x < 48; ++x)
                    for (int c = 0; c < 3; ++c)
                        mse[k] += sqr(r.film->pixel(x, y)[c] - reference.film->pixel(x, y)[c]);
        }
    EXPECT_LT(mse[0], mse[1]) << "sobol " << mse[0] << " independent " << mse[1];
    EXPECT_LT(mse[2], mse[1]) << "sobol-global " << mse[2] << " independent " << mse[1];
    RecordProperty("mse_ratio_sobol_over_independent", std::to_string(mse[0] / mse[1]));
    std::printf("MSE ratio Sobol / independent at 16 spp: %.3f, sobol-global / independent %.3f\n",
                mse[0] / mse[1], mse[2] / mse[1]);
}

}  // namespace
}  // namespace lamina
