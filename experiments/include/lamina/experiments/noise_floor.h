// A difference between two noisy renders read against its noise floor: the same statistic
// (mean or 95th-percentile CIEDE2000, ...) for a difference made of noise alone. For two
// independent renders that is the statistic between two independent renders of one side; for two
// renders that share their random numbers it is the statistic of their difference's own noise
// (pairedNoise). A difference within the floor says nothing about the models; it is
// reported as not resolved at this sample count, with the count that would resolve it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lamina/image/image_io.h"
#include "lamina/scene/scene_description.h"

namespace lamina::experiments {

/// A noise floor's twin render differs from the first by its seed alone, so every number of
/// its samples must change with the seed: refuses (InputError) sobol-global, whose film
/// positions are one pattern for every seed (the floor would be understated).
void requireSeedDependentSampler(render::SamplerKind sampler, const std::string& experiment);

/// Two images that differ by noise alone, as much as two renders of a same-seed pair do.
struct NoiseOnlyPair {
    render::RgbImage a, b;
};

/// The noise floor of a difference between two renders `a1` and `b1` that share their seed
/// (common random numbers: `fresnel --scene`'s two modes, `polarisation`'s), from a second such
/// pair `a2`, `b2` rendered with another seed. Sharing their random numbers, a1 and b1 make
/// mostly the same errors, so their difference is far less noisy than that of two independent
/// renders, whose floor would call real small differences unresolved. The noise of the
/// difference itself is measured instead: per pixel and channel, n = ((a1 - b1) - (a2 - b2)) /
/// sqrt(2) is zero on average and has the variance of a1 - b1 (the two pairs are independent
/// and alike). Returns the pair's mean m = (a1 + b1) / 2 moved apart by that noise alone,
/// m + n/2 and m - n/2: a statistic of these two (CIEDE2000, relative difference) is the floor
/// of the same statistic of a1 against b1. Centred on the mean, not on one side, so that a
/// statistic relative to one side (black in one mode: light that cancels) stays finite.
NoiseOnlyPair pairedNoise(const render::RgbImage& a1, const render::RgbImage& b1,
                          const render::RgbImage& a2, const render::RgbImage& b2);

/// A statistic of a per-pixel difference and its noise floor.
struct FlooredStatistic {
    /// `floor`: the statistic of the difference's own noise (pairedNoise): the two compared
    /// renders share their seed (common random numbers: the same paths), so their difference
    /// carries much less noise than two independent renders.
    double value = 0, floor = 0;
    /// The same statistic between the two renders of the second seed: a real difference shows
    /// in both pairs.
    double otherSeed = 0;
};

/// A per-pixel difference map of two renders that share their seed, and its mean and 95th
/// percentile (of the finite values) against their floors.
struct FlooredMap {
    std::vector<float> values;  ///< the map of a1 against b1
    FlooredStatistic mean, p95;
};

/// `map` (relativeDifferenceMap, ciede2000Map, ...) of `a1` against `b1`, its statistics' floors
/// the same statistics of `noiseOnly` (pairedNoise of the two pairs) and, as otherSeed, of the
/// second pair `a2`, `b2`.
FlooredMap flooredMap(
    const std::function<std::vector<float>(const render::RgbImage&, const render::RgbImage&)>& map,
    const render::RgbImage& a1, const render::RgbImage& b1, const render::RgbImage& a2,
    const render::RgbImage& b2, const NoiseOnlyPair& noiseOnly);

/// A difference is resolved when it exceeds this many times its floor.
inline constexpr double kResolvedOverFloor = 2.0;

struct NoiseFloorReading {
    double difference = 0, floor = 0;
    bool resolved = false;
    /// Not resolved: the samples per pixel that would resolve it, 0 when the difference shows
    /// nothing beyond the noise to estimate it from.
    long long sppToResolve = 0;
};

/// Reads `difference` (measured at `spp` samples per pixel) against `floor`. The estimate of
/// the samples that would resolve it takes the noise as adding in quadrature to the true
/// difference, T = sqrt(difference^2 - floor^2), and the floor as falling as 1/sqrt(spp)
/// (Monte Carlo): it is the spp at which kResolvedOverFloor x floor = T.
NoiseFloorReading readAgainstFloor(double difference, double floor, int spp);

/// "4.54 (noise floor 1.21)" or, within the floor, "0.93 (noise floor 0.88: not resolved at
/// 8 spp; about 120 spp would resolve it)": CIEDE2000-like numbers, two decimals.
std::string describeReading(const NoiseFloorReading& reading, int spp);

}  // namespace lamina::experiments
