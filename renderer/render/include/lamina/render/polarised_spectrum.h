// What a path carries in the polarised mode (docs/polarisation.md): a Mueller matrix for each
// of the four hero wavelengths, stored as a 4x4 matrix of SampledSpectrum (the element-wise
// spectrum arithmetic does the per-wavelength products). A camera path's throughput is the
// product of its vertices' matrices, camera side first; radiance is a matrix whose first column
// is the Stokes vector (the emitters are unpolarised, diag(Le, 0, 0, 0)), so the same
// integrator code serves all modes. Magnitudes (Russian roulette, "is anything left") are read
// from the [0][0] element, the response to unpolarised light, which is what the spectral mode
// carries: the two modes make the same decisions along a path.
#pragma once

#include "lamina/core/mueller_matrix.h"
#include "lamina/core/spectrum.h"

namespace lamina::render {

struct PolarisedSpectrum : MuellerMatrix<SampledSpectrum<float>> {
    using Base = MuellerMatrix<SampledSpectrum<float>>;
    using Element = SampledSpectrum<float>;
    using Float = float;
    static constexpr int kSize = Element::kSize;  ///< wavelengths

    PolarisedSpectrum() = default;
    /// v times the identity (0: nothing, 1: the throughput of an empty path).
    explicit PolarisedSpectrum(float v) : Base(Element(v)) {}
    PolarisedSpectrum(const Base& b) : Base(b) {}  // NOLINT: the results of Base's arithmetic

    /// The response to unpolarised light: what the spectral mode computes.
    const Element& unpolarised() const { return m[0][0]; }
    float maxValue() const { return m[0][0].maxValue(); }
    bool hasNegative() const { return m[0][0].hasNegative(); }
    bool isZero() const {
        for (const auto& row : m)
            for (const Element& e : row)
                if (!e.isZero()) return false;
        return true;
    }
    bool isFinite() const {
        for (const auto& row : m)
            for (const Element& e : row)
                if (!e.isFinite()) return false;
        return true;
    }
};

}  // namespace lamina::render
