// The random-walk coated material (bsdf/coated.h): energy, reciprocity in expectation, limit
// cases against closed forms, and sample() against the density its pdf estimator averages to.
// Every test has a fixed seed; the z-tests use |z| < 4 (two-sided 6e-5 per comparison, well
// inside the suite's family-wise 1% over the comparisons below) and the chi-square tests the
// suite's Sidak-corrected 1%.
#include <gtest/gtest.h>

#include "bsdf_cases.h"
#include "chi2_helpers.h"
#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/dielectric.h"
#include "sampled_albedo.h"

namespace lamina {
namespace {

using testing::MeanAndError;
using testing::sampledAlbedo;
using testing::Spec;
constexpr double kZ = 4.0;

std::shared_ptr<const Bxdf<Spec>> coated(const std::string& json) {
    return buildBxdf(parseMaterialArgument(json), SpectrumContext<Spec>{});
}

const CoatedBxdf<Spec>& asCoated(const Bxdf<Spec>& b) {
    return dynamic_cast<const CoatedBxdf<Spec>&>(b);
}

// The same albedo from eval() (non-delta part only): cosine-weighted directions wi.
MeanAndError evaluatedAlbedo(const Bxdf<Spec>& b, const Vec3d& wo, int n, int c = 0) {
    Pcg32 rng(2);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3d wi = squareToCosineHemisphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const double w = b.eval(wo, wi, TransportMode::Radiance)[c] / cosineHemispherePdf(wi);
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

::testing::AssertionResult agrees(const MeanAndError& a, double expected, double extra = 0) {
    const double z = (a.mean - expected) / std::sqrt(a.error * a.error + extra * extra + 1e-300);
    if (std::abs(z) < kZ) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << a.mean << " +- " << a.error << " vs " << expected << " (z = " << z << ")";
}

TEST(CoatedWalk, WhiteFurnaceClearCoatOverWhiteBase) {
    // No absorption anywhere and a smooth coat (whose boundary conserves energy exactly): every
    // photon leaves, so the albedo is 1 at every angle, from sample() and from eval() plus the
    // coat's own specular reflection F. At the material's default settings: no max_depth, the
    // walk ends by Russian roulette alone.
    for (const char* medium : {"", R"("thickness":0.5,"albedo":1,"g":0.5,)"}) {
        const auto b = coated(std::string(R"({"type":"coated","ior":1.5,)") + medium +
                              R"("base":{"type":"lambert","reflectance":1}})");
        for (double theta : {0.0, 30.0, 60.0, 85.0}) {
            const Vec3d wo = testing::directionAt(theta);
            EXPECT_TRUE(agrees(sampledAlbedo(*b, wo, 40000), 1.0)) << medium << theta;
            const double F = fresnelDielectric(wo.z, 1.5);
            EXPECT_TRUE(agrees(evaluatedAlbedo(*b, wo, 40000), 1.0 - F)) << medium << theta;
        }
    }
}

TEST(CoatedWalk, ACappedWalkIsStillAvailableAndDarker) {
    // max_depth 10, pbrt-v4's default: paths of more events are absorbed, so the white furnace
    // reflects measurably less than 1 (by more than four standard errors) at every angle, and
    // the cap is what the BSDF reports.
    const auto b = coated(
        R"({"type":"coated","ior":1.5,"max_depth":10,"base":{"type":"lambert","reflectance":1}})");
    EXPECT_EQ(asCoated(*b).maxDepth(), 10);
    EXPECT_EQ(asCoated(*coated(R"({"type":"coated","base":{"type":"lambert"}})")).maxDepth(), 0);
    for (double theta : {0.0, 60.0}) {
        const MeanAndError a = sampledAlbedo(*b, testing::directionAt(theta), 40000);
        EXPECT_LT(a.mean + kZ * a.error, 1.0) << theta;
        EXPECT_GT(a.mean, 0.9) << theta;  // the issue's 0.93 to 0.97
    }
}

TEST(CoatedWalk, AbsorbingMediumReflectsLessThanTheClearCoat) {
    const std::string base = R"("base":{"type":"lambert","reflectance":0.9}})";
    const auto clear = coated(R"({"type":"coated","roughness":0.3,)" + base);
    const auto tinted =
        coated(R"({"type":"coated","roughness":0.3,"thickness":0.3,"albedo":0.5,)" + base);
    const auto black = coated(R"({"type":"coated","roughness":0.3,"thickness":0.3,)" + base);
    for (double theta : {0.0, 45.0, 80.0}) {
        const Vec3d wo = testing::directionAt(theta);
        const MeanAndError c = sampledAlbedo(*clear, wo, 40000);
        const MeanAndError t = sampledAlbedo(*tinted, wo, 40000);
        const MeanAndError k = sampledAlbedo(*black, wo, 40000);
        EXPECT_LT(t.mean + kZ * std::hypot(t.error, c.error), c.mean) << theta;
        EXPECT_LT(k.mean + kZ * std::hypot(k.error, t.error), t.mean) << theta;
    }
}

TEST(CoatedWalk, ReciprocalInExpectation) {
    // f(wo, wi) and f(wi, wo) (without their cosines) from 400 independent estimates each.
    for (const auto& c : testing::coatedCases()) {
        const CoatedBxdf<Spec>& b = asCoated(*c.bxdf);
        for (double to : {10.0, 50.0, 75.0})
            for (double ti : {20.0, 60.0}) {
                const Vec3d wo = testing::directionAt(to, 0.0);
                const Vec3d wi = testing::directionAt(ti, 150.0);
                Pcg32 rng(99);
                double s[2] = {0, 0}, s2[2] = {0, 0};
                const int n = 400;
                for (int i = 0; i < n; ++i) {
                    const double a =
                        b.estimate(wo, wi, TransportMode::Radiance, rng).value[1] / wi.z;
                    const double r =
                        b.estimate(wi, wo, TransportMode::Radiance, rng).value[1] / wo.z;
                    s[0] += a, s2[0] += a * a, s[1] += r, s2[1] += r * r;
                }
                MeanAndError m[2];
                for (int k = 0; k < 2; ++k) {
                    m[k].mean = s[k] / n;
                    m[k].error = std::sqrt(std::max(0.0, s2[k] / n - m[k].mean * m[k].mean) / n);
                }
                EXPECT_TRUE(agrees(m[0], m[1].mean, m[1].error))
                    << c.name << " " << to << " " << ti;
            }
    }
}

TEST(CoatedWalk, IndexMatchedCoatIsTheBareBase) {
    const std::string base = R"({"type":"oren_nayar","reflectance":[0.7,0.4,0.2],"roughness":0.6})";
    const auto bare = coated(base);
    const auto b = coated(R"({"type":"coated","ior":1,"base":)" + base + "}");
    Pcg32 rng(5);
    for (int i = 0; i < 200; ++i) {
        const Vec3d wo = squareToUniformHemisphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const Vec3d wi = squareToUniformHemisphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const Spec f = b->eval(wo, wi, TransportMode::Radiance);
        const Spec g = bare->eval(wo, wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(f[c], g[c], 1e-9 * std::max(1.0, g[c]));
        ASSERT_NEAR(b->pdf(wo, wi), 0.9 * bare->pdf(wo, wi) + 0.1 / (2 * kPi<double>), 1e-9);
    }
}

TEST(CoatedWalk, OpaqueCoatAndBlackBaseLeaveTheInterfaceAlone) {
    // A perfectly absorbing thick coat, and a black base under a clear one: nothing that enters
    // comes back, so f is the rough boundary's reflection (Walter et al. 2007, eq. 20).
    const DielectricBxdf<Spec> boundary(1.5,
                                        MicrofacetDistribution<double>(NdfKind::Ggx, 0.09, 0.09));
    const std::string rough = R"({"type":"coated","roughness":0.3,)";
    const auto opaque =
        coated(rough + R"("thickness":60,"base":{"type":"lambert","reflectance":1}})");
    const auto black = coated(rough + R"("base":{"type":"lambert","reflectance":0}})");
    Pcg32 rng(6);
    for (int i = 0; i < 200; ++i) {
        const Vec3d wo = squareToUniformHemisphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const Vec3d wi = squareToUniformHemisphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const double ref = boundary.eval(wo, wi, TransportMode::Radiance)[0];
        ASSERT_NEAR(opaque->eval(wo, wi, TransportMode::Radiance)[0], ref, 1e-12 + 1e-9 * ref);
        ASSERT_NEAR(black->eval(wo, wi, TransportMode::Radiance)[0], ref, 1e-12 + 1e-9 * ref);
    }
    // Smooth coat over a black base: the albedo is the Fresnel reflectance F(theta) exactly.
    const auto smoothBlack =
        coated(R"({"type":"coated","base":{"type":"lambert","reflectance":0}})");
    for (double theta : {0.0, 40.0, 80.0}) {
        const Vec3d wo = testing::directionAt(theta);
        EXPECT_NEAR(sampledAlbedo(*smoothBlack, wo, 20000).mean, fresnelDielectric(wo.z, 1.5),
                    0.01);
    }
}

// 2 int_0^1 F(mu) mu dmu for light arriving from inside a boundary of index eta.
double internalDiffuseReflectance(double eta) {
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) / n;
        sum += fresnelDielectric(-mu, eta) * mu;
    }
    return 2.0 * sum / n;
}

TEST(CoatedWalk, SmoothCoatOverLambertMatchesTheClosedForm) {
    // Light enters with 1 - F(theta), the Lambertian base (albedo rho) returns it with a cosine
    // distribution that keeps its shape under specular internal reflection, and each time it
    // reaches the coat a fraction F_i (the cosine-weighted internal reflectance) is sent back:
    //   A(theta) = F(theta) + (1 - F(theta)) rho (1 - F_i) / (1 - rho F_i),
    // the sum of the geometric series of round trips between the base and the coat.
    const double rho = 0.6, eta = 1.5;
    const double Fi = internalDiffuseReflectance(eta);
    const auto b =
        coated(R"({"type":"coated","ior":1.5,"base":{"type":"lambert","reflectance":0.6}})");
    for (double theta : {0.0, 30.0, 60.0, 85.0}) {
        const Vec3d wo = testing::directionAt(theta);
        const double F = fresnelDielectric(wo.z, eta);
        const double A = F + (1 - F) * rho * (1 - Fi) / (1 - rho * Fi);
        EXPECT_TRUE(agrees(sampledAlbedo(*b, wo, 40000), A)) << theta;
        EXPECT_TRUE(agrees(evaluatedAlbedo(*b, wo, 40000), A - F)) << theta;
    }
}

// The unbiased density estimate averaged over `k` walks: the true density of sample().
struct AveragedDensity {
    const CoatedBxdf<Spec>& b;
    Vec3d wo;
    int k;
    mutable Pcg32 rng{11};
    double operator()(const Vec3d& wi) const {
        if (wi.z <= 0) return 0.0;
        double sum = 0;
        for (int i = 0; i < k; ++i)
            sum += b.estimate(wo, wi, TransportMode::Radiance, rng).density;
        return sum / k;
    }
};

class CoatedChi2 : public ::testing::TestWithParam<testing::BsdfCase> {};

TEST_P(CoatedChi2, SampleMatchesTheAveragedDensityEstimate) {
    const CoatedBxdf<Spec>& b = asCoated(*GetParam().bxdf);
    for (double theta : {30.0, 70.0}) {
        const Vec3d wo = testing::directionAt(theta);
        ChiSquareConfig config;
        config.significance = testing::kSignificance;
        config.testCount = 2 * int(testing::coatedCases().size());
        config.sampleCount = 50000;
        config.cosThetaBins = 16;
        config.phiBins = 32;
        config.maxSubdivisions = 1;
        const ChiSquareResult r = runChiSquareTest(
            config,
            [&](Pcg32& rng) -> std::optional<Vec3d> {
                const double uc = rng.nextDouble();
                const Vec2d u(rng.nextDouble(), rng.nextDouble());
                const auto s = b.sample(wo, uc, u, TransportMode::Radiance);
                if (!s || s->isSpecular()) return std::nullopt;
                return s->wi;
            },
            AveragedDensity{b, wo, 48});
        EXPECT_TRUE(testing::passes(r)) << theta;
    }
}

TEST_P(CoatedChi2, EvalIntegratesToTheSampledAlbedo) {
    // sample() and eval() are two estimators of one BSDF: the mean sample weight of the
    // non-delta samples equals the integral of eval over the hemisphere, per channel and in
    // both transport modes.
    const Bxdf<Spec>& b = *GetParam().bxdf;
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
        for (double theta : {10.0, 50.0, 80.0}) {
            const Vec3d wo = testing::directionAt(theta);
            for (int c = 0; c < 3; ++c) {
                Pcg32 rng(41);
                double sum = 0, sum2 = 0;
                const int n = 30000;
                for (int i = 0; i < n; ++i) {
                    const double uc = rng.nextDouble();
                    const Vec2d u(rng.nextDouble(), rng.nextDouble());
                    const auto s = b.sample(wo, uc, u, mode);
                    const double w = s && !s->isSpecular() ? s->weight[c] : 0.0;
                    sum += w, sum2 += w * w;
                }
                MeanAndError sampled{sum / n, 0};
                sampled.error = std::sqrt(std::max(0.0, sum2 / n - sqr(sampled.mean)) / n);
                Pcg32 rng2(43);
                double esum = 0, esum2 = 0;
                for (int i = 0; i < n; ++i) {
                    const Vec3d wi =
                        squareToCosineHemisphere(Vec2d(rng2.nextDouble(), rng2.nextDouble()));
                    const double w = b.eval(wo, wi, mode)[c] / cosineHemispherePdf(wi);
                    esum += w, esum2 += w * w;
                }
                const double emean = esum / n;
                const double eerr = std::sqrt(std::max(0.0, esum2 / n - emean * emean) / n);
                EXPECT_TRUE(agrees(sampled, emean, eerr))
                    << GetParam().name << " theta " << theta << " channel " << c << " mode "
                    << int(mode);
            }
        }
}

TEST_P(CoatedChi2, SampledPdfIsPdfAndValuesAreFinite) {
    const Bxdf<Spec>& b = *GetParam().bxdf;
    Pcg32 rng(3);
    for (double theta : {0.0, 45.0, 89.0})
        for (double side : {1.0, -1.0}) {
            Vec3d wo = testing::directionAt(theta);
            wo.z *= side;
            for (int i = 0; i < 300; ++i) {
                const auto s =
                    b.sample(wo, rng.nextDouble(), Vec2d(rng.nextDouble(), rng.nextDouble()),
                             TransportMode::Importance);
                if (!s) continue;
                ASSERT_TRUE(s->weight.isFinite());
                ASSERT_FALSE(s->weight.hasNegative());
                ASSERT_GT(s->wi.z * wo.z, 0.0);
                ASSERT_GT(s->pdf, 0.0);
                if (!s->isSpecular()) {
                    ASSERT_EQ(s->pdf, b.pdf(wo, s->wi));
                }
                const Spec f = b.eval(wo, s->wi, TransportMode::Importance);
                ASSERT_TRUE(f.isFinite());
                ASSERT_FALSE(f.hasNegative());
                // Deterministic per arguments: the integrators' MIS weights rely on it.
                ASSERT_EQ(f, b.eval(wo, s->wi, TransportMode::Importance));
            }
        }
}

INSTANTIATE_TEST_SUITE_P(Coated, CoatedChi2, ::testing::ValuesIn(testing::coatedCases()),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace lamina
