// Regularised incomplete gamma functions, for chi-square p-values:
// the p-value of a chi-square statistic X with k degrees of freedom is Q(k/2, X/2).
#pragma once

namespace lamina {

/// P(a, x) = gamma(a, x) / Gamma(a), the regularised lower incomplete gamma function.
double regularizedGammaP(double a, double x);
/// Q(a, x) = 1 - P(a, x), the regularised upper incomplete gamma function.
double regularizedGammaQ(double a, double x);
/// Probability that a chi-square variable with `dof` degrees of freedom exceeds `statistic`.
double chiSquarePValue(double statistic, double dof);

}  // namespace lamina
