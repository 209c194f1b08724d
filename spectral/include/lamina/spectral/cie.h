// CIE 1931 2-degree colour matching functions and CIE standard illuminants, read from Debian's
// colord-data at build time. Tabulated at 5 nm (CMFs) and interpolated linearly in between;
// zero outside the tables. All wavelengths in nm.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "lamina/core/vector.h"
#include "lamina/spectral/tabulated_curve.h"

namespace lamina {

/// The wavelength range lamina renders: the range of the CIE 1931 tables.
inline constexpr double kLambdaMin = 360.0;
inline constexpr double kLambdaMax = 830.0;

double cieX(double nm);
double cieY(double nm);
double cieZ(double nm);
/// (cieX, cieY, cieZ) with one lookup: the three tables share their grid.
Vec3d cieXyz(double nm);

/// Integral of y-bar over [kLambdaMin, kLambdaMax] (about 106.86 nm).
double cieYIntegral();

/// Integrates f(lambda) * (x-bar, y-bar, z-bar)(lambda) over the rendered range by the
/// trapezoidal rule on a 0.5 nm grid (the CMFs are piecewise linear on 5 nm knots, so this
/// is within 1e-5 relative of the exact integral of the interpolants).
template <typename F>
Vec3d integrateAgainstCmf(F&& f) {
    constexpr double h = 0.5;
    constexpr int n = static_cast<int>((kLambdaMax - kLambdaMin) / h);
    Vec3d sum(0.0);
    for (int i = 0; i <= n; ++i) {
        const double nm = kLambdaMin + h * i;
        const double w = (i == 0 || i == n) ? 0.5 * h : h;
        sum += (w * f(nm)) * cieXyz(nm);
    }
    return sum;
}

/// The CIE illuminant with that name ("D65", "A", "E", "F11", ...), or nullptr.
const TabulatedCurve* findCieIlluminant(std::string_view name);
std::vector<std::string> cieIlluminantNames();

}  // namespace lamina
