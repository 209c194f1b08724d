// thin_dielectric: R' + T' = 1 at every angle, the closed form at normal incidence, the two
// delta directions, a Monte Carlo slab of two dielectric boundaries against R', and indices
// per wavelength in spectral mode.
#include <gtest/gtest.h>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/thin_dielectric.h"
#include "lamina/core/error.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

using Rgb = Rgbd;

std::unique_ptr<Bxdf<Rgb>> thin(double ior) {
    return buildBxdf(
        parseMaterialArgument(R"({"type":"thin_dielectric","ior":)" + std::to_string(ior) + "}"),
        SpectrumContext<Rgb>{});
}

// The expectation over the lobe choice of the sample weight, per lobe: what the slab reflects
// and what it transmits.
std::pair<Rgb, Rgb> reflectedAndTransmitted(const Bxdf<Rgb>& b, const Vec3d& wo,
                                            TransportMode mode) {
    Rgb reflected(0.0), transmitted(0.0);
    // Choices at uc = 0 and uc -> 1 reach both lobes when both have probability.
    for (const double uc : {0.0, 1 - 1e-15}) {
        const auto s = b.sample(wo, uc, {0.5, 0.5}, mode);
        if (!s) continue;
        EXPECT_TRUE(s->isSpecular());
        (s->isTransmission() ? transmitted : reflected) = s->weight * s->pdf;
    }
    return {reflected, transmitted};
}

TEST(ThinDielectric, ReflectedPlusTransmittedIsOneAtEveryAngle) {
    for (const double ior : {1.5, 1.33, 2.42, 1 / 1.5, 1.0}) {
        const auto b = thin(ior);
        for (double theta = 0; theta < 90; theta += 0.5)
            for (const double side : {1.0, -1.0}) {
                const Vec3d wo(std::sin(radians(theta)), 0, side * std::cos(radians(theta)));
                for (const auto mode : {TransportMode::Radiance, TransportMode::Importance}) {
                    const auto [r, t] = reflectedAndTransmitted(*b, wo, mode);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(r[c] + t[c], 1.0, 1e-12)
                            << "ior " << ior << " theta " << theta << " side " << side;
                }
            }
    }
}

TEST(ThinDielectric, NormalIncidenceClosedForm) {
    // R = ((1.5 - 1) / (1.5 + 1))^2 = 0.04 at one boundary; the slab: R' = 2R / (1 + R).
    const auto b = thin(1.5);
    const auto [r, t] = reflectedAndTransmitted(*b, {0, 0, 1}, TransportMode::Radiance);
    const double expected = 2 * 0.04 / 1.04;  // 0.0769230769...
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r[c], expected, 1e-15);
        EXPECT_NEAR(t[c], 1 - expected, 1e-15);
    }
    // The choice probability is R' itself for a grey index, so each weight is 1.
    const auto s = b->sample({0, 0, 1}, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf, expected, 1e-15);
    EXPECT_NEAR(s->weight[0], 1.0, 1e-15);
}

TEST(ThinDielectric, MirrorAndStraightThroughWithoutRadianceScaling) {
    const auto b = thin(1.5);
    const Vec3d wo = glm::normalize(Vec3d(0.4, -0.3, 0.8));
    const auto r = b->sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    const auto tRad = b->sample(wo, 0.999, {0.5, 0.5}, TransportMode::Radiance);
    const auto tImp = b->sample(wo, 0.999, {0.5, 0.5}, TransportMode::Importance);
    ASSERT_TRUE(r && tRad && tImp);
    EXPECT_EQ(r->flags, std::uint32_t(kLobeSpecularReflection));
    EXPECT_EQ(r->wi, Vec3d(-wo.x, -wo.y, wo.z));
    EXPECT_EQ(tRad->flags, std::uint32_t(kLobeSpecularTransmission));
    EXPECT_EQ(tRad->wi, -wo);
    EXPECT_EQ(tRad->eta, 1.0);
    EXPECT_EQ(tRad->weight, tImp->weight);  // back into the same medium: no 1/eta^2
    // Deltas: nothing to evaluate.
    EXPECT_TRUE(b->eval(wo, -wo, TransportMode::Radiance).isZero());
    EXPECT_EQ(b->pdf(wo, -wo), 0.0);
}

// An explicit slab: light enters the top boundary of a smooth dielectric and bounces between
// it and the bottom one (the same boundary seen from inside, by the slab's mirror symmetry)
// until it leaves. The fraction that leaves through the top is R' (binomial, 400k walks per
// angle, fixed seed; 4.5 standard errors: significance ~1e-5 per check).
TEST(ThinDielectric, MatchesAWalkBetweenTwoDielectricBoundaries) {
    const DielectricBxdf<Rgb> boundary(1.5, MicrofacetDistribution<double>(NdfKind::Ggx, 0, 0));
    const auto b = thin(1.5);
    Pcg32 rng(2024);
    for (const double theta : {0.0, 45.0, 75.0, 88.0}) {
        const Vec3d wo(std::sin(radians(theta)), 0, std::cos(radians(theta)));
        const int n = 400000;
        int top = 0;
        for (int i = 0; i < n; ++i) {
            auto s = boundary.sample(wo, rng.nextDouble(), {0.5, 0.5}, TransportMode::Importance);
            if (!s->isTransmission()) {
                ++top;
                continue;
            }
            // Inside: each hit, mirrored onto the top boundary, sees it from below.
            for (int hit = 1;; ++hit) {
                const Vec3d inside(-s->wi.x, -s->wi.y, s->wi.z);  // -(wi mirrored in z)
                s = boundary.sample(inside, rng.nextDouble(), {0.5, 0.5},
                                    TransportMode::Importance);
                ASSERT_TRUE(s);
                if (s->isTransmission()) {
                    if (hit % 2 == 0) ++top;  // odd hits are at the bottom
                    break;
                }
            }
        }
        const double expected = reflectedAndTransmitted(*b, wo, TransportMode::Importance).first[0];
        const double p = double(top) / n;
        EXPECT_NEAR(p, expected, 4.5 * std::sqrt(expected * (1 - expected) / n))
            << "theta " << theta;
    }
}

TEST(ThinDielectric, SpectralModeUsesTheIndexOfEachWavelength) {
    const MaterialDesc desc = parseMaterialArgument(R"({"type":"thin_dielectric","ior":"bk7"})");
    auto lambda = SampledWavelengths<double>::fixed({400, 500, 600, 700});
    const SpectrumContext<SampledSpectrum<double>> context{lambda};
    const auto b = buildBxdf(desc, context);
    const IorSpectrum bk7 = *namedIor("bk7");
    const auto s = b->sample({0, 0, 1}, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s && !s->isTransmission());
    for (int i = 0; i < 4; ++i) {
        const double n = bk7.n(lambda[i]), R = sqr((n - 1) / (n + 1));
        EXPECT_NEAR(s->weight[i] * s->pdf, 2 * R / (1 + R), 1e-12) << lambda[i] << " nm";
    }
    // The transmitted direction does not depend on the wavelength: no wavelength is dropped.
    EXPECT_FALSE(lambda.secondaryTerminated());
    // RGB mode: the index at the d-line.
    const auto rgb = buildBxdf(desc, SpectrumContext<Rgb>{});
    const double nd = bk7.n(kDLineNm), Rd = sqr((nd - 1) / (nd + 1));
    const auto r = rgb->sample({0, 0, 1}, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    EXPECT_NEAR(r->weight[0] * r->pdf, 2 * Rd / (1 + Rd), 1e-12);
}

TEST(ThinDielectric, ParserTakesTheIorsOfDielectric) {
    EXPECT_EQ(parseMaterialArgument(R"({"type":"thin_dielectric"})")
                  .model.as<ThinDielectricMaterial>()
                  .ior,
              1.5);
    EXPECT_THROW(parseMaterialArgument(R"({"type":"thin_dielectric","ior":"unobtainium"})"),
                 InputError);
    EXPECT_THROW(parseMaterialArgument(R"({"type":"thin_dielectric","ior":0})"), InputError);
    EXPECT_THROW(parseMaterialArgument(R"({"type":"thin_dielectric","roughness":0.1})"),
                 InputError);
    EXPECT_THROW(parseMaterialArgument(R"({"type":"coated","base":{"type":"thin_dielectric"}})"),
                 InputError);
}

}  // namespace
}  // namespace lamina
