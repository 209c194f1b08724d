// The convergence experiment's two measurements on synthetic error logs: the fitted slope of
// log relMSE against log seconds (a power law c * t^k gives k; noise moves it by about its
// standard error) and the time to reach an error level (log-log interpolation between passes).
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/math.h"
#include "lamina/core/pcg32.h"
#include "lamina/experiments/convergence.h"

namespace lamina::experiments {
namespace {

ErrorLog::Row row(double seconds, double relmse) {
    ErrorLog::Row r{seconds, 1, {}};
    r.metrics.relmse = relmse;
    return r;
}

/// relMSE = c * t^exponent at t = 1, 2, ..., passes.
std::vector<ErrorLog::Row> powerLaw(double c, double exponent, int passes) {
    std::vector<ErrorLog::Row> rows;
    for (int k = 1; k <= passes; ++k)
        rows.push_back(row(k, c * std::pow(double(k), exponent)));
    return rows;
}

TEST(ConvergenceSlope, OfAPowerLawIsItsExponent) {
    EXPECT_NEAR(fittedSlope(powerLaw(3.0, -1.0, 100)), -1.0, 1e-12);
    EXPECT_NEAR(fittedSlope(powerLaw(0.02, -0.5, 100)), -0.5, 1e-12);
}

TEST(ConvergenceSlope, WithNoiseStaysWithinFourStandardErrorsOfMinusOne) {
    // relMSE = t^-1 * exp(0.2 z), z standard normal. Over the 91 passes from t = 10 to 100
    // the least-squares slope has standard error 0.2 / sqrt(sum (x - mean x)^2) ~ 0.035.
    Pcg32 rng(12345);
    std::vector<ErrorLog::Row> rows;
    double sxx = 0, sx = 0, n = 0;
    for (int k = 1; k <= 100; ++k) {
        const double z = std::sqrt(-2 * std::log(1 - rng.nextDouble())) *
                         std::cos(2 * kPi<double> * rng.nextDouble());
        rows.push_back(row(k, std::exp(0.2 * z) / k));
        if (k >= 10) {
            sx += std::log(double(k));
            sxx += sqr(std::log(double(k)));
            n += 1;
        }
    }
    const double standardError = 0.2 / std::sqrt(sxx - sx * sx / n);
    EXPECT_NEAR(fittedSlope(rows), -1.0, 4 * standardError);
}

TEST(ConvergenceSlope, IgnoresTheFirstTenthOfTheTime) {
    std::vector<ErrorLog::Row> rows = powerLaw(1.0, -1.0, 100);
    rows.insert(rows.begin(), row(0.5, 1e6));  // start-up: far off the line
    EXPECT_NEAR(fittedSlope(rows), -1.0, 1e-12);
}

// A busy machine: the samples double every pass, and the last pass, run while another job
// took the cores, took four times as long per sample. The slope against samples is the
// estimator's -1; the one against seconds is bent by the load (to -0.57 here).
TEST(ConvergenceSlope, AgainstSamplesIgnoresTheSecondsOfEachPass) {
    std::vector<ErrorLog::Row> rows;
    double seconds = 0;
    for (int k = 0; k < 8; ++k) {
        const int spp = 1 << k, added = k == 0 ? 1 : spp / 2;
        seconds += added * (k == 7 ? 4.0 : 1.0);
        ErrorLog::Row r{seconds, spp, {}};
        r.metrics.relmse = 0.5 / spp;
        rows.push_back(r);
    }
    EXPECT_NEAR(fittedSlope(rows, SlopeAxis::Samples), -1.0, 1e-12);
    EXPECT_NEAR(fittedSlope(rows, SlopeAxis::Seconds), -0.57, 0.01);
}

TEST(ConvergenceSlope, NeedsThreePasses) {
    EXPECT_TRUE(std::isnan(fittedSlope({})));
    EXPECT_TRUE(std::isnan(fittedSlope({row(1, 1), row(2, 0.5)})));
    EXPECT_FALSE(std::isnan(fittedSlope({row(1, 1), row(2, 0.5), row(3, 0.3)})));
}

TEST(ConvergenceTimeToLevel, InterpolatesAPowerLawExactly) {
    const std::vector<ErrorLog::Row> rows = {row(1, 1), row(2, 0.5), row(4, 0.25), row(8, 0.125)};
    EXPECT_NEAR(timeToReach(rows, 0.3), 1 / 0.3, 1e-12);  // between the passes at 2 and 4 s
    EXPECT_NEAR(timeToReach(rows, 0.25), 4.0, 1e-12);     // reached at a pass
    EXPECT_EQ(timeToReach(rows, 2.0), 1.0);               // below the level from the start
    EXPECT_TRUE(std::isnan(timeToReach(rows, 0.01)));     // never reached
}

}  // namespace
}  // namespace lamina::experiments
