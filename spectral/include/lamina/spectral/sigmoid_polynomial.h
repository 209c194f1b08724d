// The spectrum model of Jakob and Hanika 2019, "A Low-Dimensional Function Space for
// Efficient Spectral Upsampling" (Computer Graphics Forum 38(2)): a quadratic polynomial in
// wavelength passed through a sigmoid,
//   s(lambda) = S(c0 lambda^2 + c1 lambda + c2),  S(x) = 1/2 + x / (2 sqrt(1 + x^2))  (eq. 3),
// smooth and bounded to (0, 1), so it is a plausible reflectance for any colour in the gamut.
#pragma once

#include <cmath>
#include <limits>

namespace lamina {

struct SigmoidPolynomial {
    double c0 = 0, c1 = 0, c2 = 0;  ///< coefficients in nm (c0 per nm^2)

    static double sigmoid(double x) {
        if (std::isinf(x)) return x > 0 ? 1.0 : 0.0;
        return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
    }

    double operator()(double nm) const { return sigmoid((c0 * nm + c1) * nm + c2); }

    /// The constant spectrum v in [0, 1] (c0 = c1 = 0, S(c2) = v).
    static SigmoidPolynomial constant(double v) {
        SigmoidPolynomial p;
        if (v <= 0.0)
            p.c2 = -std::numeric_limits<double>::infinity();
        else if (v >= 1.0)
            p.c2 = std::numeric_limits<double>::infinity();
        else
            p.c2 = (v - 0.5) / std::sqrt(v * (1.0 - v));
        return p;
    }

    /// Converts coefficients of a polynomial in t = (lambda - start) / width to nm.
    static SigmoidPolynomial fromNormalized(double a0, double a1, double a2, double start,
                                            double width) {
        const double w2 = width * width;
        return {a0 / w2, a1 / width - 2.0 * a0 * start / w2,
                a0 * start * start / w2 - a1 * start / width + a2};
    }
};

}  // namespace lamina
