// refractiveindex.info's dispersion formulas, shared by the named glasses (ior_spectrum.cpp)
// and the n/k file reader (ior_file.cpp).
#pragma once

#include <vector>

#include "lamina/spectral/ior_spectrum.h"

namespace lamina {

/// n at `nm` of formula 1 (Sellmeier) or 2 (Sellmeier-2) with coefficients `c`.
double dispersionFormula(int formula, const std::vector<double>& c, double nm);
IorSpectrum::Curve formulaCurve(int formula, std::vector<double> c);
/// k of a dispersion formula: none.
double noAbsorption(double);

}  // namespace lamina
