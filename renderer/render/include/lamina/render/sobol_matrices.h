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

/// Column k of dimension d: the 32-bit fraction that index bit k contributes (XOR) to the point.
extern const std::uint32_t kSobolMatrices[kSobolDimensions][kSobolIndexBits];

/// Coordinate `dimension` (< kSobolDimensions) of Sobol point `index`, unscrambled, as a 32-bit
/// fraction: the XOR of the columns of the index's set bits.
inline std::uint32_t sobolSample(std::uint64_t index, int dimension) {
    const std::uint32_t* column = kSobolMatrices[dimension];
    std::uint32_t result = 0;
    for (; index; index &= index - 1)
        result ^= column[std::countr_zero(index)];
    return result;
}

}  // namespace lamina::render
