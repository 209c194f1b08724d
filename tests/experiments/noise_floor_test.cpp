// Reading a difference against its noise floor (noise_floor.h): the threshold, and the sample
// count that would resolve a difference, in closed form.
#include "lamina/experiments/noise_floor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/error.h"

namespace lamina::experiments {
namespace {

TEST(NoiseFloor, ADifferenceIsResolvedOnlyBeyondTwiceItsFloor) {
    EXPECT_TRUE(readAgainstFloor(3.0, 1.0, 8).resolved);
    EXPECT_FALSE(readAgainstFloor(2.0, 1.0, 8).resolved);  // at the threshold: not beyond it
    EXPECT_FALSE(readAgainstFloor(0.5, 1.0, 8).resolved);
    EXPECT_EQ(readAgainstFloor(3.0, 1.0, 8).sppToResolve, 0);
}

TEST(NoiseFloor, TheSamplesThatWouldResolveADifference) {
    // 1.0 against a floor of 0.6 at 16 spp: the true difference is sqrt(1 - 0.36) = 0.8, and
    // the floor falls to 0.4 (half of it) at 16 x (1.2 / 0.8)^2 = 36 spp.
    const NoiseFloorReading r = readAgainstFloor(1.0, 0.6, 16);
    EXPECT_FALSE(r.resolved);
    EXPECT_EQ(r.sppToResolve, 36);
    EXPECT_EQ(describeReading(r, 16),
              "1.00 (noise floor 0.60: not resolved at 16 spp; about 36 spp would resolve it)");
    // Nothing beyond the noise: no estimate.
    const NoiseFloorReading none = readAgainstFloor(0.5, 0.6, 16);
    EXPECT_EQ(none.sppToResolve, 0);
    EXPECT_EQ(describeReading(none, 16),
              "0.50 (noise floor 0.60: not resolved at 16 spp; no difference beyond the noise)");
    EXPECT_EQ(describeReading(readAgainstFloor(4.54, 1.21, 8), 8), "4.54 (noise floor 1.21)");
}

// A noise floor compares renders that differ by their seed: sobol-global, whose film positions
// do not change with the seed, is refused (the floor would be understated), the others pass.
TEST(NoiseFloor, RefusesASamplerWhoseFilmPositionsIgnoreTheSeed) {
    EXPECT_THROW(requireSeedDependentSampler(render::SamplerKind::SobolGlobal, "s.json"),
                 InputError);
    EXPECT_NO_THROW(requireSeedDependentSampler(render::SamplerKind::Sobol, "s.json"));
    EXPECT_NO_THROW(requireSeedDependentSampler(render::SamplerKind::Independent, "s.json"));
}

render::RgbImage grey(std::vector<float> values) {
    render::RgbImage image;
    image.width = int(values.size());
    image.height = 1;
    for (const float v : values)
        image.pixels.insert(image.pixels.end(), {v, v, v});
    return image;
}

// The noise-only pair of two same-seed pairs, in closed form: per value the pair's mean
// m = (a1 + b1) / 2 moved apart by n = ((a1 - b1) - (a2 - b2)) / sqrt(2).
TEST(NoiseFloor, APairedNoiseIsTheDifferenceOfDifferencesAroundThePairsMean) {
    const NoiseOnlyPair p =
        pairedNoise(grey({1.0f, 2.0f}), grey({0.5f, 2.0f}), grey({3.0f, 1.0f}), grey({2.9f, 1.5f}));
    const double n0 = (0.5 - 0.1) / std::sqrt(2.0), n1 = (0.0 + 0.5) / std::sqrt(2.0);
    EXPECT_NEAR(p.a.at(0, 0, 0), 0.75 + n0 / 2, 1e-6);
    EXPECT_NEAR(p.b.at(0, 0, 0), 0.75 - n0 / 2, 1e-6);
    EXPECT_NEAR(p.a.at(1, 0, 1), 2.0 + n1 / 2, 1e-6);
    EXPECT_NEAR(p.b.at(1, 0, 1), 2.0 - n1 / 2, 1e-6);
}

// The same mode twice with the same seed: no difference and no noise in it, never resolved.
TEST(NoiseFloor, TheSameRenderTwiceIsNotResolved) {
    const render::RgbImage first = grey({0.2f, 0.7f}), second = grey({0.25f, 0.6f});
    const NoiseOnlyPair p = pairedNoise(first, first, second, second);
    EXPECT_EQ(p.a.pixels, p.b.pixels);
    EXPECT_FALSE(readAgainstFloor(0.0, 0.0, 4).resolved);
}

}  // namespace
}  // namespace lamina::experiments
