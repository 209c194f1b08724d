// The optimiser behind lamina's RGB -> spectrum table (Jakob and Hanika 2019, section 4):
// for a target linear Rec.709 colour, find the sigmoid-polynomial reflectance whose colour
// under D65 matches it, by Gauss-Newton iterations on the CIELAB difference (the paper's
// choice: errors measured where they are visible). Used at build time to tabulate the sRGB
// cube and by the tests.
#pragma once

#include <array>

#include "lamina/core/spectrum.h"
#include "lamina/spectral/sigmoid_polynomial.h"

namespace lamina {

/// Coefficients in normalised wavelength t = (lambda - 360) / 470, in [0, 1].
using NormalizedCoefficients = std::array<double, 3>;

struct SigmoidFit {
    NormalizedCoefficients coefficients{};
    double residual = 0;  ///< CIELAB distance (Delta E 1976) of the result
    int iterations = 0;
};

class RgbToSpectrumFitter {
  public:
    RgbToSpectrumFitter();

    /// Fits `rgb` (linear Rec.709, in [0, 1]) starting from `start` (the neighbouring
    /// table entry; zeros for a cold start).
    SigmoidFit fit(const Rgb<double>& rgb, NormalizedCoefficients start) const;

    /// The linear Rec.709 colour of the reflectance `c` under D65 (the quantity fitted).
    Rgb<double> colorOf(const NormalizedCoefficients& c) const;

    static SigmoidPolynomial toNanometres(const NormalizedCoefficients& c);

  private:
    static constexpr int kSamples = 471;  ///< 1 nm steps over 360-830 nm
    std::array<double, kSamples> t_{};
    std::array<std::array<double, 3>, kSamples> weights_{};  ///< CMF * D65 * dlambda / norm
};

}  // namespace lamina
