// The generator matrices of the Sobol sequence in its first kSobolDimensions dimensions, as the
// sobol-global sampler takes every dimension of a sample from one global Sobol point (pbrt-v4's
// SobolSampler does the same). The matrices are generated at build time from the Joe-Kuo
// direction numbers of Debian's libboost-dev (renderer/render/tools/generate_sobol_matrices.cpp).
#pragma once

#include <bit>
#include <cstdint>

namespace lamina::render {

/// How many dimensions the table holds (Joe and Kuo's table has 21201; pbrt-v4 uses 1024).
inline constexpr int kSobolDimensions = 1024;
/// Columns per dimension: one per bit of a 64-bit index.
inline constexpr int kSobolIndexBits = 64;

/// The columns of dimensions 2p and 2p + 1 side by side, for one pass over an index's bits to
/// give both coordinates of a pair: column k of pair p has dimension 2p's 32-bit fraction for
/// index bit k in its low half and dimension 2p + 1's in its high half.
extern const std::uint64_t kSobolPairMatrices[kSobolDimensions / 2][kSobolIndexBits];

/// Coordinates 2 pair and 2 pair + 1 (pair < kSobolDimensions / 2) of Sobol point `index`,
/// unscrambled, as 32-bit fractions in the low and high half: the XOR of the columns of the
/// index's set bits.
inline std::uint64_t sobolPairSample(std::uint64_t index, int pair) {
    const std::uint64_t* column = kSobolPairMatrices[pair];
    std::uint64_t result = 0;
    for (; index; index &= index - 1)
        result ^= column[std::countr_zero(index)];
    return result;
}

/// Coordinate `dimension` (< kSobolDimensions) of Sobol point `index`, unscrambled.
inline std::uint32_t sobolSample(std::uint64_t index, int dimension) {
    return std::uint32_t(sobolPairSample(index, dimension / 2) >> (32 * (dimension % 2)));
}

}  // namespace lamina::render
