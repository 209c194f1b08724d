// Special functions the microfacet models need.
#pragma once

#include <cmath>

#include "lamina/core/math.h"

namespace lamina {

/// Inverse error function on (-1, 1). Giles 2012, "Approximating the erfinv function" (GPU
/// Computing Gems Jade, single-precision branch polynomials), refined by two Newton steps on
/// erf in double precision, so the result is accurate to double rounding.
inline double erfInv(double x) {
    if (x <= -1.0) return -INFINITY;
    if (x >= 1.0) return INFINITY;
    double w = -std::log((1.0 - x) * (1.0 + x));
    double p;
    if (w < 5.0) {
        w -= 2.5;
        p = 2.81022636e-08;
        p = 3.43273939e-07 + p * w;
        p = -3.5233877e-06 + p * w;
        p = -4.39150654e-06 + p * w;
        p = 0.00021858087 + p * w;
        p = -0.00125372503 + p * w;
        p = -0.00417768164 + p * w;
        p = 0.246640727 + p * w;
        p = 1.50140941 + p * w;
    } else {
        w = std::sqrt(w) - 3.0;
        p = -0.000200214257;
        p = 0.000100950558 + p * w;
        p = 0.00134934322 + p * w;
        p = -0.00367342844 + p * w;
        p = 0.00573950773 + p * w;
        p = -0.0076224613 + p * w;
        p = 0.00943887047 + p * w;
        p = 1.00167406 + p * w;
        p = 2.83297682 + p * w;
    }
    double y = p * x;
    // Newton on erf(y) - x: d/dy erf(y) = 2/sqrt(pi) exp(-y^2).
    for (int i = 0; i < 2; ++i) {
        const double err = std::erf(y) - x;
        y -= err / (2.0 / std::sqrt(kPi<double>) * std::exp(-y * y));
    }
    return y;
}

}  // namespace lamina
