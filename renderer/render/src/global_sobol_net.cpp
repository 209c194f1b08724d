#include "lamina/render/global_sobol_net.h"

#include <stdexcept>

#include "lamina/render/sampler.h"

namespace lamina::render {

using sobol_detail::reverseBits;
using sobol_detail::sobolDimension1;

GlobalSobolNet::GlobalSobolNet(int width, int height) {
    const int side = std::max(width, height);
    if (width < 1 || height < 1 || side > (1 << 16))
        throw std::invalid_argument("GlobalSobolNet: each side of the image in [1, 65536]");
    while ((1 << m_) < side)
        ++m_;
    // Gauss-Jordan elimination over GF(2) on the pairs (A l, l) for the unit vectors l of the
    // index bits m..2m-1, A the top m rows of dimension 1's generator matrix: when the image
    // side of each pivot pair is reduced to one bit b, its index side is column b of A^-1.
    // A is invertible because every block of 2^(2m) points of a (0, 2)-sequence puts exactly
    // one point into each pixel.
    std::array<std::uint32_t, 16> image{}, preimage{};
    for (int j = 0; j < m_; ++j) {
        image[j] = pixelOf(std::uint32_t(sobolDimension1(std::uint64_t(1) << (m_ + j))));
        preimage[j] = 1u << j;
    }
    for (int row = 0, bit = m_ - 1; bit >= 0; --bit, ++row) {
        int pivot = row;
        while (pivot < m_ && !(image[pivot] & (1u << bit)))
            ++pivot;
        if (pivot == m_) throw std::logic_error("GlobalSobolNet: a singular generator matrix");
        std::swap(image[row], image[pivot]);
        std::swap(preimage[row], preimage[pivot]);
        for (int other = 0; other < m_; ++other)
            if (other != row && (image[other] & (1u << bit))) {
                image[other] ^= image[row];
                preimage[other] ^= preimage[row];
            }
    }
    for (int row = 0; row < m_; ++row)
        inverseColumns_[m_ - 1 - row] = preimage[row];  // image[row] == 1 << (m - 1 - row)
}

std::uint32_t GlobalSobolNet::pixelOf(std::uint32_t coordinate) const {
    return m_ == 0 ? 0u : coordinate >> (32 - m_);
}

std::uint64_t GlobalSobolNet::globalIndex(int x, int y, std::uint32_t sampleIndex) const {
    // Dimension 0's top m bits are the index's low m bits reversed.
    const std::uint64_t low = pixelOf(reverseBits(std::uint32_t(x)));
    const std::uint64_t base = (std::uint64_t(sampleIndex) << (2 * m_)) | low;
    // Dimension 1 is linear in the index: the middle bits must make up the difference
    // between y and what the other bits give.
    std::uint32_t rest = pixelOf(std::uint32_t(sobolDimension1(base))) ^ std::uint32_t(y);
    std::uint32_t middle = 0;
    for (int b = 0; rest; ++b, rest >>= 1)
        if (rest & 1u) middle ^= inverseColumns_[b];
    return base | (std::uint64_t(middle) << m_);
}

Vec2<float> GlobalSobolNet::pixelPosition(std::uint64_t index) const {
    // The bits below the pixel's m, as a fraction of the pixel.
    const std::uint32_t u = reverseBits(std::uint32_t(index)) << m_;
    const std::uint32_t v = std::uint32_t(sobolDimension1(index)) << m_;
    return {sobol_detail::unitFloat(u), sobol_detail::unitFloat(v)};
}

}  // namespace lamina::render
