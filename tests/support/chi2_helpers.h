// Shared conventions of the statistical tests: the family-wise significance level and how a
// chi-square result is reported on failure.
#pragma once

#include <gtest/gtest.h>

#include "lamina/core/chi_square_test.h"

namespace lamina::testing {

/// Every statistical suite in lamina runs at a family-wise significance of 1%, split over its
/// tests with the Sidak correction.
inline constexpr double kSignificance = 0.01;

inline ::testing::AssertionResult passes(const ChiSquareResult& r) {
    if (r.passed) return ::testing::AssertionSuccess() << r.message;
    return ::testing::AssertionFailure() << r.message;
}

}  // namespace lamina::testing
