// The directional albedo of a BSDF estimated from its sampler, with its standard error: what the
// energy and agreement tests of the coated and layered materials compare.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/pcg32.h"

namespace lamina::testing {

struct MeanAndError {
    double mean = 0, error = 0;
};

/// Directional albedo from sample(): the mean weight (channel `c`) of `n` samples from
/// PCG32(seed), delta samples included, an absorbed sample counting 0.
inline MeanAndError sampledAlbedo(const Bxdf<Rgb<double>>& b, const Vec3d& wo, int n, int c = 0,
                                  std::uint64_t seed = 1) {
    Pcg32 rng(seed);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const double uc = rng.nextDouble();
        const Vec2d u(rng.nextDouble(), rng.nextDouble());
        const auto s = b.sample(wo, uc, u, TransportMode::Radiance);
        const double w = s ? s->weight[c] : 0.0;
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

}  // namespace lamina::testing
