// The chi-square utility must reject what is wrong, or every other statistical test is
// meaningless. Each case here feeds it a density that does not match the sampler and asserts
// a rejection at the suite's significance level.
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/core/warp.h"

namespace lamina {
namespace {

Vec2d next2(Pcg32& r) {
    const double a = r.nextDouble();
    return {a, r.nextDouble()};
}

ChiSquareConfig config() {
    ChiSquareConfig c;
    c.significance = testing::kSignificance;
    c.testCount = 4;
    return c;
}

std::optional<Vec3d> cosineSample(Pcg32& r) {
    return squareToCosineHemisphere(next2(r));
}

TEST(ChiSquareSelfTest, RejectsADensityScaledBy1Point05) {
    const ChiSquareResult r = runChiSquareTest(
        config(), cosineSample, [](const Vec3d& w) { return 1.05 * cosineHemispherePdf(w); });
    EXPECT_FALSE(r.passed) << r.message;
}

TEST(ChiSquareSelfTest, RejectsADensityOfTheWrongShape) {
    // Cosine-distributed samples tested against the uniform-hemisphere density.
    const ChiSquareResult r = runChiSquareTest(
        config(), cosineSample, [](const Vec3d& w) { return uniformHemispherePdf(w); });
    EXPECT_FALSE(r.passed) << r.message;
}

TEST(ChiSquareSelfTest, RejectsSamplesWhereTheDensityIsZero) {
    // The sampler covers the sphere; the density claims only the upper hemisphere.
    const ChiSquareResult r = runChiSquareTest(
        config(), [](Pcg32& rng) { return std::optional(squareToUniformSphere(next2(rng))); },
        [](const Vec3d& w) { return w.z > 0 ? 2.0 * uniformSpherePdf<double>() : 0.0; });
    EXPECT_FALSE(r.passed) << r.message;
}

TEST(ChiSquareSelfTest, AcceptsTheCorrectDensityWithTheSameSettings) {
    const ChiSquareResult r = runChiSquareTest(
        config(), cosineSample, [](const Vec3d& w) { return cosineHemispherePdf(w); });
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-3);
}

TEST(ChiSquareSelfTest, SidakCorrection) {
    EXPECT_NEAR(sidakCorrectedAlpha(0.01, 1), 0.01, 1e-15);
    // 1 - (1 - a)^(1/k) for k = 10.
    EXPECT_NEAR(sidakCorrectedAlpha(0.01, 10), 1.0 - std::pow(0.99, 0.1), 1e-15);
    EXPECT_LT(sidakCorrectedAlpha(0.01, 10), 0.01 / 10 * 1.01);
}

}  // namespace
}  // namespace lamina

#include "bsdf_cases.h"

namespace lamina {
namespace {

TEST(ChiSquareSelfTest, RejectsABsdfWhosePdfIsNotItsSampler) {
    // Samples from Walter's NDF sampling, tested against the visible-normal density of the
    // same GGX lobe: both are valid densities, but not of each other.
    using testing::Spec;
    const MicrofacetDistribution<double> d(NdfKind::Ggx, 0.5, 0.5);
    const ConductorBxdf<Spec> walter(
        MicrofacetReflectionLobe<Spec>(d, testing::goldFresnel(), MicrofacetSampling::Walter));
    const ConductorBxdf<Spec> vndf(MicrofacetReflectionLobe<Spec>(d, testing::goldFresnel()));
    const Vec3d wo = testing::directionAt(60.0);
    const ChiSquareResult r = runChiSquareTest(
        config(),
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            const auto s = walter.sample(wo, 0.5, Vec2d(rng.nextDouble(), rng.nextDouble()),
                                         TransportMode::Radiance);
            if (!s) return std::nullopt;
            return s->wi;
        },
        [&](const Vec3d& wi) { return vndf.pdf(wo, wi); });
    EXPECT_FALSE(r.passed) << r.message;
}

}  // namespace
}  // namespace lamina
