// Student's t distribution, for tests of two means whose variances are estimated from a few
// independent batches (the reciprocity and convergence experiments).
#pragma once

namespace lamina {

/// The regularized incomplete beta function I_x(a, b), a, b > 0, x in [0, 1].
double regularizedIncompleteBeta(double a, double b, double x);

/// P(|T| >= |t|) for T with `dof` degrees of freedom (dof may be fractional, > 0).
double studentTTwoSidedPValue(double t, double dof);

/// Welch-Satterthwaite degrees of freedom of the difference of two means whose variances
/// (of the means) va and vb were estimated with na - 1 and nb - 1 degrees of freedom.
double welchDegreesOfFreedom(double va, double na, double vb, double nb);

}  // namespace lamina
