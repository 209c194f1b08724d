// Per-sample random numbers. A pixel's stream depends only on (seed, pixel, sample index), so
// an image is bit-identical for any thread count and tile order.
//   IndependentSampler  PCG32 seeded by a hash of (seed, pixel, sample).
//   SobolSampler        2D Sobol points with Owen scrambling by hashing (Burley 2020,
//                       "Practical Hash-based Owen Scrambling", JCGT 9(4)); each pair of
//                       dimensions gets its own shuffle of the sample index and its own
//                       scramble ("padding", so every 2D pair is a (0, 2)-sequence); the
//                       three seeds of a pair come from one 64-bit hash of (pixel, pair).
//   sobol-global        as pbrt-v4's SobolSampler, every number of a sample is a coordinate of
//                       one point of a single Sobol sequence over the whole image: the film
//                       position (getPixel2D) is its dimensions 0 and 1, unscrambled
//                       (global_sobol_net.h: a fixed pattern, the same for every seed), the
//                       wavelength number (getWavelength1D) dimension 2, and every later
//                       get1D/get2D the next pair of dimensions from 4 (sobol_matrices.h, 1024 of
//                       them, Joe and Kuo's direction numbers), each Owen-scrambled with this
//                       pixel's and dimension pair's seeds. So film position, wavelength, light
//                       and BSDF samples are stratified together within a pixel, where the
//                       Sobol sampler pairs its 2D points at random: a light's sharp reflection
//                       in a smooth plate, which depends on film position and light sample
//                       jointly, has about a third of the Sobol sampler's variance on Veach's
//                       MIS scene (docs/performance.md). Past the table's dimensions the numbers
//                       are the Sobol sampler's.
#pragma once

#include <bit>
#include <cstdint>
#include <stdexcept>

#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/vector.h"
#include "lamina/render/global_sobol_net.h"
#include "lamina/render/sobol_matrices.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

namespace sobol_detail {

/// Reverses the 32 bits of x: the byte swap is one instruction, then the bits of each byte.
inline std::uint32_t reverseBits(std::uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

/// Sobol dimension 1 (primitive polynomial x + 1, direction numbers v_k = v_{k-1} ^
/// (v_{k-1} >> 1) from v_0 = 2^31); dimension 0 is the van der Corput sequence. The index may
/// exceed 32 bits (the global net of sobol-global); the result keeps 32 bits.
constexpr std::uint32_t sobolDimension1(std::uint64_t index) {
    std::uint32_t result = 0, v = 1u << 31;
    for (; index; index >>= 1, v ^= v >> 1)
        if (index & 1u) result ^= v;
    return result;
}

/// Sobol dimension 1 in the bit-reversed domain: reverseBits(sobolDimension1(reverseBits(y))).
/// It is linear over GF(2) in y, so it is the XOR of one table entry per byte of y (the
/// tables hold the images of the 256 values of each byte), four lookups instead of a loop
/// over 32 bits.
class ReversedSobolDimension1 {
  public:
    constexpr ReversedSobolDimension1() {
        std::uint32_t column[32] = {};  // the image of bit j of y
        for (int j = 0; j < 32; ++j) {
            // Bit j of y is bit 31 - j of x = reverseBits(y).
            const std::uint32_t x = 1u << (31 - j);
            const std::uint32_t r = sobolDimension1(x);
            std::uint32_t reversed = 0;
            for (int b = 0; b < 32; ++b)
                if (r & (1u << b)) reversed |= 1u << (31 - b);
            column[j] = reversed;
        }
        for (int byte = 0; byte < 4; ++byte)
            for (int v = 0; v < 256; ++v) {
                std::uint32_t image = 0;
                for (int bit = 0; bit < 8; ++bit)
                    if (v & (1 << bit)) image ^= column[8 * byte + bit];
                table_[byte][v] = image;
            }
    }
    std::uint32_t operator()(std::uint32_t y) const {
        return table_[0][y & 0xFFu] ^ table_[1][(y >> 8) & 0xFFu] ^ table_[2][(y >> 16) & 0xFFu] ^
               table_[3][y >> 24];
    }

  private:
    std::uint32_t table_[4][256] = {};
};

inline constexpr ReversedSobolDimension1 kReversedSobolDimension1{};

/// Burley 2020, listing 3: the Laine-Karras-style hash that permutes bits only downwards;
/// applied to reversed bits, reverse(LK(reverse(x), seed)) is a nested uniform (Owen) scramble
/// of x.
/// A 32-bit fixed-point fraction as a float in [0, 1): its top 24 bits, exactly.
inline float unitFloat(std::uint32_t v) {
    return std::min(kOneMinusEpsilon<float>, float(v >> 8) * 0x1p-24f);
}

inline std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

}  // namespace sobol_detail

/// What every sample of one pixel shares: the hash of (seed, pixel) and the pixel's part of
/// each dimension's hash. The renderer computes it once per pixel, not once per sample.
struct PixelSeed {
    PixelSeed(std::uint64_t seed, int x, int y)
        : pixel(hashValues({seed, std::uint64_t(x), std::uint64_t(y)})),
          dimensionBase(hashValues({pixel})),
          dimensionSalt(0x9e3779b97f4a7c15ULL + (dimensionBase << 6u)),
          x(x),
          y(y) {}

    std::uint64_t pixel;
    std::uint64_t dimensionBase;  ///< hashValues({pixel})
    /// The part of hashValues({pixel, dim})'s last step that does not depend on dim.
    std::uint64_t dimensionSalt;
    int x, y;  ///< the pixel, for the global net of sobol-global
};

class PixelSampler {
  public:
    /// `net`: the film's global net, which sobol-global needs (and the others ignore).
    PixelSampler(SamplerKind kind, std::uint64_t seed, int x, int y, std::uint32_t sampleIndex,
                 const GlobalSobolNet* net = nullptr)
        : PixelSampler(kind, PixelSeed(seed, x, y), sampleIndex, net) {}
    PixelSampler(SamplerKind kind, const PixelSeed& pixel, std::uint32_t sampleIndex,
                 const GlobalSobolNet* net = nullptr)
        : kind_(kind),
          reversedIndex_(sobol_detail::reverseBits(sampleIndex)),
          dimensionBase_(pixel.dimensionBase),
          dimensionSalt_(pixel.dimensionSalt),
          net_(net) {
        // The Sobol sampler needs no generator; seeding one costs as much as a dimension.
        if (kind_ == SamplerKind::Independent)
            rng_ = Pcg32(hashValues({pixel.pixel, sampleIndex}), pixel.pixel);
        if (kind_ == SamplerKind::SobolGlobal) {
            if (!net_)
                throw std::invalid_argument(
                    "PixelSampler: sobol-global needs the film's global net");
            globalIndex_ = net_->globalIndex(pixel.x, pixel.y, sampleIndex);
        }
    }

    /// The next dimension pair as the sample's position in its pixel (the camera sample's
    /// film position, before the pixel filter): get2D(), except for sobol-global, whose
    /// position is the pixel's point of the global net (its dimensions 0 and 1).
    Vec2<float> getPixel2D() {
        if (kind_ != SamplerKind::SobolGlobal) return get2D();
        ++dimension_;
        return net_->pixelPosition(globalIndex_);
    }

    /// The next dimension as the number that draws the path's wavelengths (the spectral
    /// modes): get1D(), except for sobol-global, which takes dimension 2 of the sample's global
    /// point (pbrt-v4's SobolSampler draws its wavelengths from its dimension 2), so that a
    /// pixel's film positions and wavelengths are stratified together.
    float getWavelength1D() {
        if (kind_ != SamplerKind::SobolGlobal) return get1D();
        const DimensionSeeds s = dimensionSeeds(dimension_++);
        return toFloat(scramble(sobolSample(globalIndex_, kWavelengthDimension), s.first));
    }

    float get1D() {
        if (kind_ == SamplerKind::Independent) return get2D().x;
        // The first coordinate of the next 2D point, without computing the second.
        using namespace sobol_detail;
        const DimensionSeeds s = dimensionSeeds(dimension_++);
        if (const int d = nextGlobalPair(); d >= 0)
            return toFloat(scramble(sobolSample(globalIndex_, d), s.first));
        const std::uint32_t y = laineKarrasPermutation(reversedIndex_, s.shuffle);
        return toFloat(scramble(y, s.first));
    }

    /// Moves past the next dimension (what get1D or get2D would return) without computing
    /// it, for a number a path does not use this time (the lens point of a pinhole camera, a
    /// Russian roulette that cannot end the path yet): every later dimension then holds the
    /// numbers it holds when the skipped one is drawn, so images do not change.
    void skip() {
        if (kind_ == SamplerKind::Independent) {
            rng_.nextUint32();
            rng_.nextUint32();
        }
        nextGlobalPair();
        ++dimension_;
    }

    /// get1D() when the number is `used`; otherwise skip() and 0, for a number the path has
    /// no use for this time (the lobe choice of a BSDF of one lobe, the choice of a light
    /// among one).
    float get1DIfUsed(bool used) {
        if (used) return get1D();
        skip();
        return 0.0f;
    }
    /// get2D() when the numbers are `used`; otherwise skip() and the centre (a pinhole's lens
    /// point).
    Vec2<float> get2DIfUsed(bool used) {
        if (used) return get2D();
        skip();
        return Vec2<float>(0.5f);
    }

    /// The next dimension pair of the sample: the sample index shuffled by a nested uniform
    /// scramble of its own (so pairs are decorrelated), then Sobol dimensions 0 and 1 of the
    /// shuffled index, each scrambled with a seed of its own. Everything is computed in the
    /// bit-reversed domain where it can be, so that each scramble (reverse, permute, reverse)
    /// costs one reversal at most, with scramble(x, s) = reverse(LK(reverse(x), s)) and the
    /// van der Corput sequence vdC = reverse:
    ///   shuffled = scramble(index, s)        = reverse(y),  y = LK(reverse(index), s)
    ///   a = scramble(vdC(shuffled), s1)      = reverse(LK(reverse(y), s1))
    ///   b = scramble(Sobol1(shuffled), s2)   = reverse(LK(reversedSobol1(y), s2))
    Vec2<float> get2D() {
        if (kind_ == SamplerKind::Independent) {
            ++dimension_;
            const float a = rng_.nextFloat();
            return {a, rng_.nextFloat()};
        }
        using namespace sobol_detail;
        const DimensionSeeds s = dimensionSeeds(dimension_++);
        if (const int d = nextGlobalPair(); d >= 0) {
            const std::uint64_t both = sobolPairSample(globalIndex_, d / 2);
            return {toFloat(scramble(std::uint32_t(both), s.first)),
                    toFloat(scramble(std::uint32_t(both >> 32), s.second))};
        }
        const std::uint32_t y = laineKarrasPermutation(reversedIndex_, s.shuffle);
        const std::uint32_t a = scramble(y, s.first);
        const std::uint32_t b =
            reverseBits(laineKarrasPermutation(kReversedSobolDimension1(y), s.second));
        return {toFloat(a), toFloat(b)};
    }

  private:
    /// The three scramble seeds of dimension pair `dim`, from one 64-bit hash of (pixel, dim):
    /// its low and high halves, and the high half of its product with an odd constant (which
    /// depends on every bit of the hash). pbrt-v4's PaddedSobolSampler likewise takes the
    /// index permutation's and both coordinates' seeds from one 64-bit hash. One mixBits per
    /// pair, where three were used before.
    struct DimensionSeeds {
        std::uint32_t shuffle, first, second;
    };
    DimensionSeeds dimensionSeeds(std::uint32_t dim) const {
        const std::uint64_t h = dimensionHash(dim);
        return {std::uint32_t(h), std::uint32_t(h >> 32),
                std::uint32_t((h * kSecondSeedMultiplier) >> 32)};
    }
    /// hashValues({pixelSeed, dim}), what depends on the pixel alone done once per pixel
    /// (PixelSeed; the sum dim + salt is the same number in either order).
    std::uint64_t dimensionHash(std::uint32_t dim) const {
        return mixBits(dimensionBase_ ^ (dim + dimensionSalt_));
    }
    /// An odd multiplier (so the product is a bijection of the hash) of good spectral quality
    /// for a 64-bit LCG: Steele and Vigna 2022, "Computationally easy, spectrally good
    /// multipliers for congruential pseudorandom number generators" (a 64-bit one they list).
    static constexpr std::uint64_t kSecondSeedMultiplier = 0xd1342543de82ef95ULL;
    static float toFloat(std::uint32_t v) { return sobol_detail::unitFloat(v); }
    /// A nested uniform (Owen) scramble of a 32-bit fraction: reverse(LK(reverse(v), seed)).
    static std::uint32_t scramble(std::uint32_t v, std::uint32_t seed) {
        using namespace sobol_detail;
        return reverseBits(laineKarrasPermutation(reverseBits(v), seed));
    }
    /// sobol-global: the first of the two Sobol dimensions the next get1D/get2D/skip takes from
    /// the global point, and moves past them; -1 for the other samplers and past the table
    /// (then the numbers are the Sobol sampler's). Dimensions 0 and 1 are the film position,
    /// 2 the wavelength number, 3 is left out so that every later pair is a pair of the table
    /// (2p, 2p + 1: one pass over the index's bits gives both); a get1D uses the first of its
    /// pair, so that skipping a number or drawing it leaves every later one unchanged.
    int nextGlobalPair() {
        if (kind_ != SamplerKind::SobolGlobal || nextGlobalDimension_ + 1 >= kSobolDimensions)
            return -1;
        const int d = nextGlobalDimension_;
        nextGlobalDimension_ += 2;
        return d;
    }
    static constexpr int kWavelengthDimension = 2;

    SamplerKind kind_;
    std::uint32_t reversedIndex_;
    std::uint64_t dimensionBase_, dimensionSalt_;
    Pcg32 rng_;
    const GlobalSobolNet* net_;
    std::uint64_t globalIndex_ = 0;  ///< sobol-global: the sample's index in the global net
    int nextGlobalDimension_ = kWavelengthDimension + 2;  ///< sobol-global's next free pair
    std::uint32_t dimension_ = 0;
};

}  // namespace lamina::render
