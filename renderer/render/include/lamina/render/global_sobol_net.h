// The film positions of the `sobol-global` sampler: like pbrt-v4's SobolSampler, one global,
// unscrambled 2D Sobol sequence (dimensions 0 and 1) laid over the image, scaled so that a
// pixel is an elementary interval 2^-m x 2^-m (2^m the image's larger side rounded up to a
// power of two). Sample j of pixel (x, y) is the j-th point of that sequence falling in the
// pixel, found directly by the elementary-interval enumeration of Grünschloß, Raab and Keller
// 2012 ("Enumerating Quasi-Monte Carlo Point Sequences in Elementary Intervals", section 3):
// the low m bits of the global index are fixed by x (dimension 0 is the van der Corput
// sequence, the index's bits reversed), the next m bits solve a linear system over GF(2) for y
// (dimension 1's generator matrix restricted to those bits, inverted once), and the sample
// index j is the bits above. Since the Sobol pair is a (0, 2)-sequence, the first 2^k samples
// of a pixel are a (0, k, 2)-net in it.
//
// The pattern is deterministic: it does not depend on the seed, so renders with different
// seeds are not independent in the film position (the other dimensions stay lamina's
// per-pixel Owen-scrambled Sobol points).
#pragma once

#include <array>
#include <cstdint>

#include "lamina/core/vector.h"

namespace lamina::render {

class GlobalSobolNet {
  public:
    /// The net over an image of width x height pixels (each side at most 2^16).
    GlobalSobolNet(int width, int height);

    /// The index in the global Sobol sequence of sample `sampleIndex` of pixel (x, y).
    std::uint64_t globalIndex(int x, int y, std::uint32_t sampleIndex) const;
    /// The position of the global point of that index in its pixel, each coordinate in
    /// [0, 1).
    Vec2<float> pixelPosition(std::uint64_t index) const;

    /// m: the grid is 2^m x 2^m pixels.
    int log2Resolution() const { return m_; }

  private:
    /// The top m bits of a 32-bit fixed-point coordinate (the pixel it falls in).
    std::uint32_t pixelOf(std::uint32_t coordinate) const;

    int m_ = 0;
    /// Column b: the index bits m..2m-1 (shifted down by m) whose dimension-1 image has top m
    /// bits 1 << b: the inverse of the m x m generator submatrix over GF(2).
    std::array<std::uint32_t, 16> inverseColumns_{};
};

}  // namespace lamina::render
