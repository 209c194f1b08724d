#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/incomplete_gamma.h"

namespace lamina {
namespace {

TEST(IncompleteGamma, ClosedForms) {
    // Q(1, x) = exp(-x); P(1/2, x) = erf(sqrt(x)).
    for (double x : {0.1, 0.5, 1.0, 2.0, 5.0, 20.0}) {
        EXPECT_NEAR(regularizedGammaQ(1.0, x), std::exp(-x), 1e-12);
        EXPECT_NEAR(regularizedGammaP(0.5, x), std::erf(std::sqrt(x)), 1e-12);
        EXPECT_NEAR(regularizedGammaP(3.0, x) + regularizedGammaQ(3.0, x), 1.0, 1e-12);
    }
}

TEST(IncompleteGamma, ChiSquareCriticalValues) {
    // Tabulated critical values of the chi-square distribution.
    EXPECT_NEAR(chiSquarePValue(3.841459, 1), 0.05, 1e-6);
    EXPECT_NEAR(chiSquarePValue(6.634897, 1), 0.01, 1e-6);
    EXPECT_NEAR(chiSquarePValue(18.307038, 10), 0.05, 1e-6);
    EXPECT_NEAR(chiSquarePValue(124.342113, 100), 0.05, 1e-6);
    // Large dof: the mean of chi-square(k) is k and its median is close to it.
    EXPECT_NEAR(chiSquarePValue(2047.0 - 2.0 / 3.0, 2047), 0.5, 0.01);
}

TEST(IncompleteGamma, RejectsInvalidArguments) {
    EXPECT_THROW(regularizedGammaP(0.0, 1.0), std::domain_error);
    EXPECT_THROW(regularizedGammaQ(1.0, -1.0), std::domain_error);
    EXPECT_EQ(chiSquarePValue(INFINITY, 3), 0.0);
}

}  // namespace
}  // namespace lamina
