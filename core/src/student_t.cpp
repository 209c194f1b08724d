#include "lamina/core/student_t.h"

#include <cmath>
#include <limits>

namespace lamina {

namespace {

// The continued fraction of I_x(a, b) (Abramowitz and Stegun 26.5.8), evaluated by the
// modified Lentz method; it converges quickly for x < (a + 1) / (a + b + 2).
double betaContinuedFraction(double a, double b, double x) {
    constexpr double kTiny = 1e-300;
    constexpr double kEpsilon = 1e-15;
    double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
    if (std::abs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    double result = d;
    for (int m = 1; m <= 1000; ++m) {
        const double m2 = 2.0 * m;
        // Even step: d_{2m} = m (b - m) x / ((a + 2m - 1)(a + 2m)).
        double num = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
        d = 1.0 + num * d;
        c = 1.0 + num / c;
        if (std::abs(d) < kTiny) d = kTiny;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        result *= d * c;
        // Odd step: d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)).
        num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
        d = 1.0 + num * d;
        c = 1.0 + num / c;
        if (std::abs(d) < kTiny) d = kTiny;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        result *= delta;
        if (std::abs(delta - 1.0) < kEpsilon) break;
    }
    return result;
}

}  // namespace

double regularizedIncompleteBeta(double a, double b, double x) {
    if (!(x > 0.0)) return 0.0;
    if (!(x < 1.0)) return 1.0;
    // x^a (1 - x)^b / (a B(a, b)) times the continued fraction, using the symmetry
    // I_x(a, b) = 1 - I_{1-x}(b, a) where the fraction converges slowly.
    const double logFront =
        std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
    const double front = std::exp(logFront);
    if (x < (a + 1.0) / (a + b + 2.0)) return front * betaContinuedFraction(a, b, x) / a;
    return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

double studentTTwoSidedPValue(double t, double dof) {
    if (!std::isfinite(t)) return 0.0;
    if (!std::isfinite(dof)) return std::erfc(std::abs(t) / std::sqrt(2.0));
    // P(|T| >= t) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2).
    return regularizedIncompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double welchDegreesOfFreedom(double va, double na, double vb, double nb) {
    const double num = (va + vb) * (va + vb);
    const double den = (na > 1 ? va * va / (na - 1) : 0.0) + (nb > 1 ? vb * vb / (nb - 1) : 0.0);
    if (!(den > 0.0)) return std::numeric_limits<double>::infinity();
    return num / den;
}

}  // namespace lamina
