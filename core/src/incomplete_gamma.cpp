#include "lamina/core/incomplete_gamma.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lamina {
namespace {

constexpr int kMaxIterations = 100000;
constexpr double kEpsilon = 1e-15;

// log of x^a e^-x / Gamma(a): the prefactor common to both expansions.
double logPrefactor(double a, double x) {
    return a * std::log(x) - x - std::lgamma(a);
}

// P(a, x) by its power series, which converges quickly for x < a + 1:
// P = x^a e^-x / Gamma(a) * sum_n x^n / (a (a+1) ... (a+n)).
double gammaPSeries(double a, double x) {
    double term = 1.0 / a, sum = term, ap = a;
    for (int n = 0; n < kMaxIterations; ++n) {
        ap += 1.0;
        term *= x / ap;
        sum += term;
        if (std::abs(term) < std::abs(sum) * kEpsilon) break;
    }
    return sum * std::exp(logPrefactor(a, x));
}

// Q(a, x) by Legendre's continued fraction, evaluated with the modified Lentz method; it
// converges quickly for x > a + 1.
double gammaQContinuedFraction(double a, double x) {
    constexpr double tiny = std::numeric_limits<double>::min() / kEpsilon;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEpsilon) break;
    }
    return std::exp(logPrefactor(a, x)) * h;
}

void checkArguments(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0))
        throw std::domain_error("incomplete gamma: needs a > 0 and x >= 0");
}

}  // namespace

double regularizedGammaP(double a, double x) {
    checkArguments(a, x);
    if (x == 0.0) return 0.0;
    return x < a + 1.0 ? gammaPSeries(a, x) : 1.0 - gammaQContinuedFraction(a, x);
}

double regularizedGammaQ(double a, double x) {
    checkArguments(a, x);
    if (x == 0.0) return 1.0;
    return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

double chiSquarePValue(double statistic, double dof) {
    if (std::isinf(statistic)) return 0.0;
    return regularizedGammaQ(0.5 * dof, 0.5 * std::max(statistic, 0.0));
}

}  // namespace lamina
