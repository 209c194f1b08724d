// The windowed piecewise-constant distribution of portal lights: every window's integral is the
// sum of the cells it covers (fractions of cut cells included), samples stay in their window,
// and their histogram fits the density restricted to the window (chi-square, significance 0.01
// over the suite, Sidak-corrected).
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/windowed_distribution_2d.h"

namespace lamina {
namespace {

constexpr int kSuiteTests = 3;
constexpr int kNx = 8, kNy = 6;

/// Uneven cells, a zero row and a zero column among them, so that a wrong row or column
/// shows.
WindowedDistribution2D unevenGrid() {
    std::vector<double> v(std::size_t(kNx) * kNy);
    Pcg32 rng(3);
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i)
            v[std::size_t(j) * kNx + std::size_t(i)] =
                (i == 5 || j == 2) ? 0.0 : 0.1 + 3.0 * rng.nextDouble();
    return WindowedDistribution2D(kNx, kNy, v);
}

/// The integral over a window by brute force: each cell's value times its overlap.
double bruteIntegral(const std::vector<double>& v, const UnitWindow& w) {
    double sum = 0;
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i) {
            const double ox = std::max(
                0.0, std::min(w.hi.x, (i + 1.0) / kNx) - std::max(w.lo.x, double(i) / kNx));
            const double oy = std::max(
                0.0, std::min(w.hi.y, (j + 1.0) / kNy) - std::max(w.lo.y, double(j) / kNy));
            sum += v[std::size_t(j) * kNx + std::size_t(i)] * ox * oy;
        }
    return sum;
}

TEST(WindowedDistribution2D, AWindowsIntegralIsTheSumOfTheCellsItCovers) {
    std::vector<double> v(std::size_t(kNx) * kNy);
    Pcg32 rng(5);
    for (double& x : v)
        x = rng.nextDouble();
    const WindowedDistribution2D d(kNx, kNy, v);
    for (int k = 0; k < 200; ++k) {
        const double a = rng.nextDouble(), b = rng.nextDouble(), c = rng.nextDouble(),
                     e = rng.nextDouble();
        const UnitWindow w{{std::min(a, b), std::min(c, e)}, {std::max(a, b), std::max(c, e)}};
        EXPECT_NEAR(d.integral(w), bruteIntegral(v, w), 1e-12) << k;
    }
    EXPECT_NEAR(d.integral(UnitWindow{}), bruteIntegral(v, UnitWindow{}), 1e-12);
}

TEST(WindowedDistribution2D, SamplesStayInTheirWindowWithTheDensityTheyReport) {
    const WindowedDistribution2D d = unevenGrid();
    const UnitWindow w{{0.13, 0.05}, {0.71, 0.88}};
    Pcg32 rng(9);
    for (int k = 0; k < 10000; ++k) {
        double pdf;
        const auto p = d.sample({rng.nextDouble(), rng.nextDouble()}, w, pdf);
        ASSERT_TRUE(p);
        EXPECT_GE(p->x, w.lo.x);
        EXPECT_LE(p->x, w.hi.x);
        EXPECT_GE(p->y, w.lo.y);
        EXPECT_LE(p->y, w.hi.y);
        EXPECT_NEAR(pdf, d.pdf(*p, w), 1e-9 * pdf);
        EXPECT_GT(pdf, 0.0);
    }
    EXPECT_EQ(d.pdf({0.9, 0.5}, w), 0.0);
    // A window inside the zero column holds nothing.
    double pdf;
    EXPECT_FALSE(d.sample({0.5, 0.5}, UnitWindow{{0.63, 0.1}, {0.74, 0.9}}, pdf));
}

void expectFits(const UnitWindow& w) {
    const WindowedDistribution2D d = unevenGrid();
    ChiSquareConfig c;
    c.domain = ChiSquareDomain::Plane;
    c.planeMin = w.lo;
    c.planeMax = w.hi;
    c.phiBins = 30;
    c.cosThetaBins = 30;
    c.testCount = kSuiteTests;
    c.significance = testing::kSignificance;
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        c,
        [&](Pcg32& r) -> std::optional<Vec3d> {
            double pdf;
            const double a = r.nextDouble();
            const auto p = d.sample({a, r.nextDouble()}, w, pdf);
            if (!p) return std::nullopt;
            return Vec3d(p->x, p->y, 0.0);
        },
        [&](const Vec3d& p) {
            return d.pdf({p.x, p.y}, w);
        })));
}

TEST(WindowedDistribution2DChi2, TheWholeSquare) {
    expectFits(UnitWindow{});
}

TEST(WindowedDistribution2DChi2, AWindowThatCutsCells) {
    expectFits(UnitWindow{{0.13, 0.05}, {0.71, 0.88}});
}

TEST(WindowedDistribution2DChi2, AWindowWithinOneRow) {
    expectFits(UnitWindow{{0.02, 0.52}, {0.97, 0.6}});
}

}  // namespace
}  // namespace lamina
