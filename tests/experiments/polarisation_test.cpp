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
    const Sample crossed = blockOf(r.spectral.relative, r.width, kCrossed);
    const Sample parallel = blockOf(r.spectral.relative, r.width, kParallel);
    EXPECT_LT(std::abs(crossed.mean - 2.0), kZ * crossed.standardError + 1e-6) << crossed.mean;
    EXPECT_LT(std::abs(parallel.mean - 2.0 / 3.0), kZ * parallel.standardError + 1e-6)
        << parallel.mean;
    // What the summary reports: every statistic resolved, far above its floor.
    const int spp = r.polarised.spp;
    for (const FlooredStatistic& s : {r.spectral.meanRelative, r.spectral.p95Relative,
                                      r.spectral.meanDeltaE, r.spectral.p95DeltaE})
        EXPECT_TRUE(readAgainstFloor(s.value, s.floor, spp).resolved)
            << s.value << " against " << s.floor;
    // The relative difference, a closed form of the mirrors, stands far above its noise.
    EXPECT_GT(r.spectral.meanRelative.value, 10 * r.spectral.meanRelative.floor);
    EXPECT_GT(r.spectral.p95Relative.value, 10 * r.spectral.p95Relative.floor);
    // The p95 of the relative difference is the crossed pair's 2.
    EXPECT_NEAR(r.spectral.p95Relative.value, 2.0, 1e-3);
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

}  // namespace
}  // namespace lamina::experiments
