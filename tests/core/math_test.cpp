#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lamina/core/math.h"
#include "lamina/core/vector.h"

namespace lamina {
namespace {

TEST(Math, SafeFunctionsNeverReturnNaN) {
    EXPECT_EQ(safeSqrt(-1e-9), 0.0);
    EXPECT_EQ(safeSqrt(-1e-9f), 0.0f);
    EXPECT_DOUBLE_EQ(safeAcos(1.0 + 1e-7), 0.0);
    EXPECT_DOUBLE_EQ(safeAcos(-1.0 - 1e-7), kPi<double>);
    EXPECT_DOUBLE_EQ(safeAsin(2.0), kPi<double> / 2);
    EXPECT_EQ(safeDiv(1.0, 0.0), 0.0);
    EXPECT_EQ(safeDiv(1.0, 0.0, 5.0), 5.0);
    EXPECT_EQ(safeDiv(6.0, 3.0), 2.0);
}

TEST(Math, ClampTurnsNaNIntoLowerBound) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(clamp(nan, 0.0, 1.0), 0.0);
    EXPECT_EQ(saturate(1.5f), 1.0f);
    EXPECT_EQ(saturate(-0.5), 0.0);
}

TEST(Math, SqrPow5Polynomial) {
    EXPECT_EQ(sqr(3), 9);
    EXPECT_DOUBLE_EQ(pow5(0.5), 0.03125);
    const double c[] = {1.0, 2.0, 3.0};  // 1 + 2x + 3x^2
    EXPECT_DOUBLE_EQ(evalPolynomial(2.0, c), 17.0);
}

// The polynomial sine and cosine against double precision on a grid of 4 million angles over
// [-pi/4, pi/4] (spacing 3.9e-7): within 3 ulps of the correctly rounded value, odd and even
// as sin and cos are, and exact at 0.
TEST(Math, SinCosWithinQuarterPiIsWithinThreeUlps) {
    auto ulps = [](float got, double exact) {
        const float rounded = float(exact);
        const float ulp = std::nextafter(std::abs(rounded), 2.0f) - std::abs(rounded);
        return std::abs(double(got) - exact) / double(ulp);
    };
    double worstSin = 0, worstCos = 0;
    const int n = 4000000;
    for (int i = 0; i <= n; ++i) {
        const float a = std::min(kPi<float> / 4.0f,
                                 -kPi<float> / 4.0f + kPi<float> / 2.0f * float(i) / float(n));
        const SinCos sc = sinCosWithinQuarterPi(a);
        worstSin = std::max(worstSin, ulps(sc.sin, std::sin(double(a))));
        worstCos = std::max(worstCos, ulps(sc.cos, std::cos(double(a))));
        const SinCos negated = sinCosWithinQuarterPi(-a);
        ASSERT_EQ(negated.sin, -sc.sin) << a;
        ASSERT_EQ(negated.cos, sc.cos) << a;
    }
    EXPECT_LE(worstSin, 3.0);
    EXPECT_LE(worstCos, 3.0);
    EXPECT_EQ(sinCosWithinQuarterPi(0.0f).sin, 0.0f);
    EXPECT_EQ(sinCosWithinQuarterPi(0.0f).cos, 1.0f);
}

TEST(Math, OneMinusEpsilonIsBelowOne) {
    EXPECT_LT(kOneMinusEpsilon<float>, 1.0f);
    EXPECT_LT(kOneMinusEpsilon<double>, 1.0);
    EXPECT_EQ(std::nextafter(kOneMinusEpsilon<float>, 2.0f), 1.0f);
}

TEST(Vector, SafeNormalizeOfZeroIsZero) {
    EXPECT_EQ(safeNormalize(Vec3d(0.0)), Vec3d(0.0));
    const Vec3d n = safeNormalize(Vec3d(3.0, 0.0, 4.0));
    EXPECT_DOUBLE_EQ(n.x, 0.6);
    EXPECT_DOUBLE_EQ(n.z, 0.8);
}

TEST(Vector, ReflectMirrorsAboutNormal) {
    const Vec3d r = reflect(Vec3d(1.0, 0.0, 1.0), Vec3d(0.0, 0.0, 1.0));
    EXPECT_DOUBLE_EQ(r.x, -1.0);
    EXPECT_DOUBLE_EQ(r.z, 1.0);
}

}  // namespace
}  // namespace lamina
