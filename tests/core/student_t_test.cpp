// Student's t and the incomplete beta function against tabulated values.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/student_t.h"

namespace lamina {
namespace {

TEST(StudentT, IncompleteBetaMatchesClosedForms) {
    // I_x(a, 1) = x^a; I_x(1, b) = 1 - (1 - x)^b; I_0.5(2, 3) = 11/16.
    EXPECT_NEAR(regularizedIncompleteBeta(3.5, 1, 0.3), std::pow(0.3, 3.5), 1e-13);
    EXPECT_NEAR(regularizedIncompleteBeta(1, 4.2, 0.7), 1 - std::pow(0.3, 4.2), 1e-13);
    EXPECT_NEAR(regularizedIncompleteBeta(2, 3, 0.5), 11.0 / 16.0, 1e-13);
    EXPECT_EQ(regularizedIncompleteBeta(2, 3, 0), 0.0);
    EXPECT_EQ(regularizedIncompleteBeta(2, 3, 1), 1.0);
}

TEST(StudentT, TwoSidedPValuesMatchTables) {
    // Critical values of the t distribution (two-sided): t_{0.975, 10} = 2.228139,
    // t_{0.995, 30} = 2.749996, t_{0.95, 1} = 6.313752; the normal limit z_{0.995} = 2.575829.
    EXPECT_NEAR(studentTTwoSidedPValue(2.228139, 10), 0.05, 1e-6);
    EXPECT_NEAR(studentTTwoSidedPValue(-2.749996, 30), 0.01, 1e-6);
    EXPECT_NEAR(studentTTwoSidedPValue(6.313752, 1), 0.10, 1e-6);
    EXPECT_NEAR(studentTTwoSidedPValue(2.575829, INFINITY), 0.01, 1e-6);
    EXPECT_NEAR(studentTTwoSidedPValue(2.575829, 1e7), 0.01, 1e-5);
    EXPECT_EQ(studentTTwoSidedPValue(0, 5), 1.0);
}

TEST(StudentT, WelchDegreesOfFreedom) {
    // Equal variances and sizes: 2 (n - 1).
    EXPECT_NEAR(welchDegreesOfFreedom(1.0, 16, 1.0, 16), 30.0, 1e-12);
    // One exact side (a reference): the other's n - 1.
    EXPECT_NEAR(welchDegreesOfFreedom(2.0, 32, 0.0, 1), 31.0, 1e-12);
}

}  // namespace
}  // namespace lamina
