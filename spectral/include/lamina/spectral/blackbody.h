// Planck's law: the spectral radiance of a black body at temperature T (kelvin),
//   B(lambda, T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k_B T)) - 1)   [W sr^-1 m^-3],
// with the 2019 SI values of h, c and k_B (exact by definition).
#pragma once

#include <cmath>

namespace lamina {

inline double blackbodyRadiance(double nm, double kelvin) {
    constexpr double h = 6.62607015e-34, c = 299792458.0, kB = 1.380649e-23;
    const double l = nm * 1e-9;
    return 2.0 * h * c * c / (l * l * l * l * l) / std::expm1(h * c / (l * kB * kelvin));
}

/// B normalised to 1 at its peak (Wien's displacement law, b = 2.897771955e-3 m K).
inline double blackbodyNormalized(double nm, double kelvin) {
    const double peakNm = 2.897771955e-3 / kelvin * 1e9;
    return blackbodyRadiance(nm, kelvin) / blackbodyRadiance(peakNm, kelvin);
}

}  // namespace lamina
