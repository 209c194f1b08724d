// `lamina polarisation` (polarisation.h) against closed forms.
//
// On scenes/polarisation/two-mirrors.json (glass mirrors at Brewster's angle, Rp = 0): the
// crossed pair is black in the polarised mode and U = 10 ((Rs + Rp) / 2)^2 in the spectral mode,
// a relative difference |U - 0| / (U / 2) = 2 in every pixel; the parallel pair is 2U in the
// polarised mode, a relative difference |U - 2U| / (3U / 2) = 2/3. The experiment must report
// that difference resolved above its noise floor, and the parallel pair's light, s-polarised by
// two reflections, with DoLP 1 along the image's x (AoLP 0).
//
// On one glass mirror at 45 degrees (written here): unpolarised light reflected once has
// S = [Rs + Rp, Rs - Rp, 0, 0] / 2 in the s/p frame, so DoLP = (Rs - Rp) / (Rs + Rp), with Rs
// and Rp from lamina's complex Fresnel amplitudes. The mirrors' index does not depend on the
// wavelength, so each sample's DoLP is that value: the tolerance is float rounding (1e-4).
//
// Fixed seed (the scenes'); the block means of the relative difference are z-tested at
// significance 0.001 (|z| < 3.29) against the standard deviation of the block's pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "lamina/core/fresnel_amplitudes.h"
#include "lamina/core/spectrum.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/polarisation.h"
#include "scratch_directory.h"
#include "source_files.h"

namespace lamina::experiments {
namespace {

constexpr double kZ = 3.29;  // two-sided significance 0.001

struct Block {
    int x0, x1, y0, y1;  ///< inclusive: the pixels a pair's first mirror fills (64x12 film)
};
constexpr Block kCrossed{5, 18, 2, 9}, kParallel{45, 58, 2, 9};

struct Sample {
    double mean = 0, standardError = 0;
};

Sample blockOf(const std::vector<float>& values, int width, const Block& b) {
    double sum = 0, sumSq = 0, n = 0;
    for (int y = b.y0; y <= b.y1; ++y)
        for (int x = b.x0; x <= b.x1; ++x) {
            const double v = values[std::size_t(y) * width + x];
            sum += v;
            sumSq += v * v;
            n += 1;
        }
    const double mean = sum / n;
    const double variance = std::max(0.0, (sumSq - n * mean * mean) / (n - 1));
    return {mean, std::sqrt(variance / n)};
}

PolarisationResult runOn(const std::string& scene) {
    PolarisationInputs in;
    in.scene = scene;
    in.spp = 16;
    return runPolarisation(in);
}

TEST(PolarisationExperiment, CrossedMirrorsAtBrewstersAngleDifferAboveTheNoiseFloor) {
    const PolarisationResult r =
        runOn(testing::sourceFile("scenes/polarisation/two-mirrors.json").string());
    ASSERT_EQ(r.width, 64);
    ASSERT_EQ(r.height, 12);
    const Sample crossed = blockOf(r.relative, r.width, kCrossed);
    const Sample parallel = blockOf(r.relative, r.width, kParallel);
    EXPECT_LT(std::abs(crossed.mean - 2.0), kZ * crossed.standardError + 1e-6) << crossed.mean;
    EXPECT_LT(std::abs(parallel.mean - 2.0 / 3.0), kZ * parallel.standardError + 1e-6)
        << parallel.mean;
    // What the summary reports: every statistic resolved, far above its floor.
    const int spp = r.polarised.spp;
    for (const FlooredStatistic& s : {r.meanRelative, r.p95Relative, r.meanDeltaE, r.p95DeltaE})
        EXPECT_TRUE(readAgainstFloor(s.value, s.floor, spp).resolved)
            << s.value << " against " << s.floor;
    // The relative difference, a closed form of the mirrors, stands far above its noise.
    EXPECT_GT(r.meanRelative.value, 10 * r.meanRelative.floor);
    EXPECT_GT(r.p95Relative.value, 10 * r.p95Relative.floor);
    // The p95 of the relative difference is the crossed pair's 2.
    EXPECT_NEAR(r.p95Relative.value, 2.0, 1e-3);
    // The parallel pair's light is s-polarised: fully, along the image's x.
    const Sample dolp = blockOf(r.dolp, r.width, kParallel);
    const Sample aolp = blockOf(r.aolp, r.width, kParallel);
    EXPECT_NEAR(dolp.mean, 1.0, 1e-4);
    EXPECT_NEAR(aolp.mean, 0.0, 0.05);  // degrees
    // The crossed pair has no light to be polarised.
    for (int y = kCrossed.y0; y <= kCrossed.y1; ++y)
        for (int x = kCrossed.x0; x <= kCrossed.x1; ++x)
            EXPECT_FALSE(r.lit[std::size_t(y) * r.width + x]) << x << ", " << y;
}

class PolarisationExperimentScene : public lamina::testing::ScratchDirectoryTest {};

TEST_F(PolarisationExperimentScene, OneReflectionHasTheDegreeOfPolarisationOfFresnel) {
    // An orthographic camera looks down at a glass mirror (reflection only) tilted by 45
    // degrees about x, which reflects it into a lamp along +y.
    const auto scene = write("one-mirror.json", R"({
      "camera": {"type": "orthographic", "position": [0, 0, 5], "look_at": [0, 0, 0],
                 "up": [0, 1, 0], "screen_window": [-0.3, 0.3, -0.3, 0.3]},
      "film": {"resolution": [8, 8], "filter": {"type": "box", "radius": 0.5}},
      "sampler": {"spp": 4},
      "materials": {"mirror": {"type": "conductor", "eta": 1.5, "k": 0},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "rectangle", "material": "mirror",
         "transform": [{"rotate": {"axis": [-1, 0, 0], "angle": 45}}]},
        {"type": "rectangle", "material": "lamp", "emission": {"radiance": 1},
         "transform": [{"scale": 2}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"translate": [0, 2, 0]}]}]})");
    const PolarisationResult r = runOn(scene.string());
    const auto a = fresnelAmplitudes(std::cos(0.25 * std::numbers::pi), std::complex<double>(1.5));
    const double rs = std::norm(a.rs), rp = std::norm(a.rp);
    const double expected = (rs - rp) / (rs + rp);
    ASSERT_GT(expected, 0.8);  // 0.8316: far from both 0 and 1
    for (std::size_t i = 0; i < r.dolp.size(); ++i) {
        ASSERT_TRUE(r.lit[i]) << i;
        EXPECT_NEAR(r.dolp[i], expected, 1e-4) << i;
        // s is x, the image's right: the light is polarised horizontally.
        EXPECT_NEAR(r.aolp[i], 0.0, 0.05) << i;
    }
    EXPECT_NEAR(r.meanDolp, expected, 1e-4);
}

// The noise floor of the two modes' same-seed difference (noise_floor.h, pairedNoise). Two
// metal mirrors (n = 1.5, k = 12, the same at every wavelength) at 56.31 degrees with crossed
// planes of incidence reflect a coloured lamp into the camera: the polarised mode gives
// L Rs Rp, the spectral mode L ((Rs + Rp) / 2)^2, a relative difference of 0.063% in every
// pixel (Fresnel in closed form below). The lamp's colour makes the spectral sampling of both
// modes noisy (about 9% between renders of two seeds at 4 spp), but the two modes share their
// paths and wavelengths, so their difference is 0.063% of each sample and its own noise is
// tiny: the floor of that noise resolves it, where the floor of two independent renders could
// not.
TEST_F(PolarisationExperimentScene, ASmallRealDifferenceIsResolvedAgainstTheNoiseOfTheDifference) {
    const auto scene = write("crossed-metal.json", R"({
      "camera": {"type": "orthographic", "position": [0, 0, 5], "look_at": [0, 0, 0],
                 "up": [0, 1, 0], "screen_window": [-1.75, -1.25, -0.2, 0.2]},
      "film": {"resolution": [10, 8], "filter": {"type": "box", "radius": 0.5}},
      "integrator": {"type": "path", "max_depth": 4},
      "materials": {"metal": {"type": "conductor", "eta": 1.5, "k": 12},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "rectangle", "material": "metal",
         "transform": [{"scale": 0.6}, {"rotate": {"axis": [-1, 0, 0], "angle": 56.309932}},
                       {"translate": [-1.5, 0, 0]}]},
        {"type": "rectangle", "material": "metal",
         "transform": [{"scale": 1.2},
                       {"rotate": {"axis": [0.524097, -0.851658, 0], "angle": 77.681478}},
                       {"translate": [-1.5, 1.846154, -0.769231]}]},
        {"type": "rectangle", "material": "lamp", "emission": {"radiance": [10, 1, 0.1]},
         "transform": [{"scale": 0.75},
                       {"rotate": {"axis": [0.358979, 0.933346, 0], "angle": 81.493072}},
                       {"translate": [-3.346154, 2.556213, -1.065089]}]}]})");
    PolarisationInputs in;
    in.scene = scene.string();
    in.spp = 4;
    const PolarisationResult r = runPolarisation(in);
    const auto a = fresnelAmplitudes(std::cos(std::atan(1.5)), std::complex<double>(1.5, 12));
    const double rs = std::norm(a.rs), rp = std::norm(a.rp);
    const double polarised = rs * rp, spectral = sqr((rs + rp) / 2);
    const double expected = (spectral - polarised) / ((spectral + polarised) / 2);
    ASSERT_NEAR(expected, 6.33e-4, 1e-6);
    // Every pixel's difference is the closed form (its noise cancels: the ratio of the modes
    // is the same at every wavelength), to float rounding.
    EXPECT_NEAR(r.meanRelative.value, expected, 2e-5);
    EXPECT_NEAR(r.meanRelative.otherSeed, expected, 2e-5);
    EXPECT_EQ(r.comparedPixels, 80u);
    EXPECT_TRUE(readAgainstFloor(r.meanRelative.value, r.meanRelative.floor, 4).resolved)
        << r.meanRelative.value << " against " << r.meanRelative.floor;
    EXPECT_TRUE(readAgainstFloor(r.meanDeltaE.value, r.meanDeltaE.floor, 4).resolved)
        << r.meanDeltaE.value << " against " << r.meanDeltaE.floor;
    // The floor of two independent renders (the spectral mode with two seeds) is far above
    // the difference: read against it, it would not be resolved.
    render::RenderOptions o;
    o.spp = 4;
    o.mode = render::RenderModeKind::Spectral;
    const render::SceneDesc desc = render::loadScene(scene);
    const render::RgbImage s1 = filmImage(*render::renderScene(desc, o).film);
    o.seed = 12345;
    const render::RgbImage s2 = filmImage(*render::renderScene(desc, o).film);
    double independent = 0;
    for (std::size_t i = 0; i < s1.pixels.size() / 3; ++i) {
        const double y1 =
            luminance(Rgb<double>(s1.pixels[3 * i], s1.pixels[3 * i + 1], s1.pixels[3 * i + 2]));
        const double y2 =
            luminance(Rgb<double>(s2.pixels[3 * i], s2.pixels[3 * i + 1], s2.pixels[3 * i + 2]));
        independent += std::abs(y1 - y2) / ((y1 + y2) / 2) / double(s1.pixels.size() / 3);
    }
    EXPECT_FALSE(readAgainstFloor(r.meanRelative.value, independent, 4).resolved) << independent;
    EXPECT_GT(independent, 20 * r.meanRelative.value);
}

// A scene of diffuse walls: polarisation changes nothing, and the same-seed difference of the
// two modes, whatever is left of it, is not resolved above the noise of the difference.
TEST_F(PolarisationExperimentScene, NoDifferenceIsNotResolved) {
    PolarisationInputs in;
    in.scene = lamina::testing::sourceFile("scenes/cornell-box.json").string();
    in.spp = 4;
    in.overrides.resolution = {16, 16};
    const PolarisationResult r = runPolarisation(in);
    for (const FlooredStatistic& s : {r.meanRelative, r.p95Relative, r.meanDeltaE, r.p95DeltaE})
        EXPECT_FALSE(readAgainstFloor(s.value, s.floor, 4).resolved)
            << s.value << " against " << s.floor;
}

}  // namespace
}  // namespace lamina::experiments
