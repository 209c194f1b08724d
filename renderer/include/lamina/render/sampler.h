// Per-sample random numbers. A pixel's stream depends only on (seed, pixel, sample index), so
// an image is bit-identical for any thread count and tile order.
//   IndependentSampler  PCG32 seeded by a hash of (seed, pixel, sample).
//   SobolSampler        2D Sobol points with Owen scrambling by hashing (Burley 2020,
//                       "Practical Hash-based Owen Scrambling", JCGT 9(4)); each pair of
//                       dimensions gets its own shuffle of the sample index and its own
//                       scramble ("padding", so every 2D pair is a (0, 2)-sequence).
#pragma once

#include <bit>
#include <cstdint>

#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/vector.h"
#include "lamina/render/scene_description.h"

namespace lamina::render {

namespace sobol_detail {

inline std::uint32_t reverseBits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

/// Sobol dimension 1 (primitive polynomial x + 1, direction numbers v_k = v_{k-1} ^
/// (v_{k-1} >> 1) from v_0 = 2^31); dimension 0 is the van der Corput sequence.
inline std::uint32_t sobolDimension1(std::uint32_t index) {
    std::uint32_t result = 0, v = 1u << 31;
    for (; index; index >>= 1, v ^= v >> 1)
        if (index & 1u) result ^= v;
    return result;
}

/// Burley 2020, listing 3: the Laine-Karras-style hash that permutes bits only downwards,
/// applied to reversed bits it is a nested uniform (Owen) scramble.
inline std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

inline std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

}  // namespace sobol_detail

class PixelSampler {
  public:
    PixelSampler(SamplerKind kind, std::uint64_t seed, int x, int y, std::uint32_t sampleIndex)
        : kind_(kind),
          index_(sampleIndex),
          pixelSeed_(hashValues({seed, std::uint64_t(x), std::uint64_t(y)})),
          rng_(hashValues({pixelSeed_, sampleIndex}), pixelSeed_) {}

    float get1D() { return get2D().x; }

    Vec2<float> get2D() {
        const std::uint32_t dim = dimension_++;
        if (kind_ == SamplerKind::Independent) {
            const float a = rng_.nextFloat();
            return {a, rng_.nextFloat()};
        }
        using namespace sobol_detail;
        const auto s = std::uint32_t(hashValues({pixelSeed_, dim}));
        const std::uint32_t shuffled = nestedUniformScramble(index_, s);
        const std::uint32_t a = nestedUniformScramble(reverseBits(shuffled), mixSeed(s, 1));
        const std::uint32_t b = nestedUniformScramble(sobolDimension1(shuffled), mixSeed(s, 2));
        return {toFloat(a), toFloat(b)};
    }

  private:
    static std::uint32_t mixSeed(std::uint32_t s, std::uint32_t k) {
        return std::uint32_t(mixBits((std::uint64_t(s) << 8) ^ k));
    }
    static float toFloat(std::uint32_t v) {
        return std::min(kOneMinusEpsilon<float>, float(v >> 8) * 0x1p-24f);
    }

    SamplerKind kind_;
    std::uint32_t index_;
    std::uint64_t pixelSeed_;
    Pcg32 rng_;
    std::uint32_t dimension_ = 0;
};

}  // namespace lamina::render
