// Chi-square goodness of fit of every warp against its own density (significance 0.01 over
// the suite, Sidak-corrected).
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/core/warp.h"

namespace lamina {
namespace {

constexpr int kSuiteTests = 8;

ChiSquareConfig sphereConfig() {
    ChiSquareConfig c;
    c.testCount = kSuiteTests;
    c.significance = testing::kSignificance;
    return c;
}

ChiSquareConfig planeConfig(Vec2d lo, Vec2d hi) {
    ChiSquareConfig c = sphereConfig();
    c.domain = ChiSquareDomain::Plane;
    c.planeMin = lo;
    c.planeMax = hi;
    c.phiBins = 40;
    c.cosThetaBins = 40;
    return c;
}

Vec2d next2(Pcg32& rng) {
    const double a = rng.nextDouble();
    return {a, rng.nextDouble()};
}

TEST(WarpChi2, UniformSphere) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        sphereConfig(), [](Pcg32& r) { return std::optional(squareToUniformSphere(next2(r))); },
        [](const Vec3d&) { return uniformSpherePdf<double>(); })));
}

TEST(WarpChi2, UniformHemisphere) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        sphereConfig(), [](Pcg32& r) { return std::optional(squareToUniformHemisphere(next2(r))); },
        [](const Vec3d& w) { return uniformHemispherePdf(w); })));
}

TEST(WarpChi2, CosineHemisphere) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        sphereConfig(), [](Pcg32& r) { return std::optional(squareToCosineHemisphere(next2(r))); },
        [](const Vec3d& w) { return cosineHemispherePdf(w); })));
}

TEST(WarpChi2, WideCone) {
    const double cosMax = std::cos(radians(60.0));
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        sphereConfig(),
        [=](Pcg32& r) { return std::optional(squareToUniformCone(next2(r), cosMax)); },
        [=](const Vec3d& w) { return uniformConePdf(w, cosMax); })));
}

TEST(WarpChi2, NarrowCone) {
    // A 10-degree cone covers few cells of a 32-row grid: use a finer cos-theta resolution.
    const double cosMax = std::cos(radians(10.0));
    ChiSquareConfig c = sphereConfig();
    c.cosThetaBins = 512;
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        c, [=](Pcg32& r) { return std::optional(squareToUniformCone(next2(r), cosMax)); },
        [=](const Vec3d& w) { return uniformConePdf(w, cosMax); })));
}

TEST(WarpChi2, ConcentricDisk) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        planeConfig({-1, -1}, {1, 1}),
        [](Pcg32& r) {
            const Vec2d p = squareToUniformDiskConcentric(next2(r));
            return std::optional(Vec3d(p, 0.0));
        },
        [](const Vec3d& p) { return uniformDiskPdf(Vec2d(p)); })));
}

// The single-precision map takes its sine and cosine from a polynomial (math.h).
TEST(WarpChi2, ConcentricDiskInSinglePrecision) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        planeConfig({-1, -1}, {1, 1}),
        [](Pcg32& r) {
            const Vec2f p = squareToUniformDiskConcentric(Vec2f(next2(r)));
            return std::optional(Vec3d(Vec2d(p), 0.0));
        },
        [](const Vec3d& p) { return uniformDiskPdf(Vec2d(p)); })));
}

TEST(WarpChi2, UniformTriangle) {
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        planeConfig({0, 0}, {1, 1}),
        [](Pcg32& r) {
            const Vec2d b = squareToUniformTriangle(next2(r));
            return std::optional(Vec3d(b, 0.0));
        },
        [](const Vec3d& p) { return uniformTrianglePdf(Vec2d(p)); })));
}

TEST(WarpChi2, ConeThroughItsFrame) {
    // A cone around an arbitrary axis: exercises Frame + warp together, as lights will.
    const Vec3d axis = glm::normalize(Vec3d(0.3, -0.4, -0.8));
    const Frame<double> f = Frame<double>::fromNormal(axis);
    const double cosMax = std::cos(radians(35.0));
    EXPECT_TRUE(testing::passes(runChiSquareTest(
        sphereConfig(),
        [&](Pcg32& r) { return std::optional(f.toWorld(squareToUniformCone(next2(r), cosMax))); },
        [&](const Vec3d& w) { return uniformConePdf(f.toLocal(w), cosMax); })));
}

}  // namespace
}  // namespace lamina
