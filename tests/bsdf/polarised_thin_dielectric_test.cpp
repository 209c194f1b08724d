// The polarised thin_dielectric (incoherent_slab.h, docs/polarisation.md): its reflection and
// transmission matrices are the series of the slab's internal bounces summed for s and p apart.
// Checked against the slab built event by event from the polarised smooth dielectric (an
// independent computation: the dielectric's own delta lobes, frames and all, multiplied in the
// order light meets them), the lossless energy balance for every polarised input, and the
// closed forms at normal incidence and at Brewster's angle (a one-plate pile-of-plates
// polariser transmits light of degree of polarisation R_s). Broken once on purpose: the
// reflection's higher orders summed with |r'_s conj(r'_p)| for r'_s conj(r'_p) (the sign of
// the internal reflection's s-p correlation lost) fails the event-by-event comparison.
#include <gtest/gtest.h>

#include <numbers>

#include "bsdf_cases.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/thin_dielectric.h"

namespace lamina {
namespace {

using testing::Spec;
using Mueller = MuellerMatrix<Spec>;

Vec3d fromAngle(double thetaDegrees, double azimuth = 0.4) {
    const double t = thetaDegrees * std::numbers::pi / 180.0;
    return {std::sin(t) * std::cos(azimuth), std::sin(t) * std::sin(azimuth), std::cos(t)};
}

/// The matrix (not over the lobe's probability) of the delta lobe of `b` that takes light
/// travelling along `in` to `out`, in their canonical frames.
Mueller deltaMueller(const Bxdf<Spec>& b, const Vec3d& in, const Vec3d& out) {
    const bool reflection = in.z * out.z < 0.0;
    const auto s =
        b.sample(out, reflection ? 0.0 : 1.0 - 1e-12, {0.5, 0.5}, TransportMode::Radiance);
    EXPECT_TRUE(s && s->isSpecular() && s->isTransmission() != reflection);
    if (!s) return {};
    EXPECT_LT(glm::length(s->wi + in), 1e-12) << "the lobe does not take in to out";
    return b.sampleMueller(out, *s, TransportMode::Radiance) * s->pdf;
}

/// The slab's second boundary (glass above, air below) is the first turned by pi about x.
Vec3d turned(const Vec3d& v) {
    return {v.x, -v.y, -v.z};
}

/// deltaMueller for the lower boundary, through the turned upper one, its frames turned back
/// and written in the canonical frames of the world directions.
Mueller lowerBoundary(const Bxdf<Spec>& glass, const Vec3d& in, const Vec3d& out) {
    Mueller m = deltaMueller(glass, turned(in), turned(out));
    turnInputFrame(m, doubledFrameTurn(StokesFrame<double>{in, stokesAxis(in)},
                                       turned(stokesAxis(turned(in)))));
    turnOutputFrame(m, doubledFrameTurn(StokesFrame<double>{out, turned(stokesAxis(turned(out)))},
                                        stokesAxis(out)));
    return m;
}

struct SlabMatrices {
    Mueller reflection, transmission;
};

/// Reflection of light travelling along `in` (downwards) into wo, and its transmission on
/// along `in`, summed over the first `orders` internal round trips of the event-by-event slab.
SlabMatrices eventByEvent(double eta, const Vec3d& in, int orders) {
    const DielectricBxdf<Spec> glass(eta, MicrofacetDistribution<double>(NdfKind::Ggx, 0.0, 0.0));
    const Vec3d wo(in.x, in.y, -in.z);
    const Vec3d down(in.x / eta, in.y / eta, -std::sqrt(1.0 - (1.0 - in.z * in.z) / (eta * eta)));
    const Vec3d up(down.x, down.y, -down.z);
    const Mueller outside = deltaMueller(glass, in, wo);
    const Mueller enter = deltaMueller(glass, in, down);
    const Mueller leaveTop = deltaMueller(glass, up, wo);
    const Mueller insideTop = deltaMueller(glass, up, down);
    const Mueller insideBottom = lowerBoundary(glass, down, up);
    const Mueller leaveBottom = lowerBoundary(glass, down, in);
    SlabMatrices slab{outside, {}};
    Mueller afterEntering = enter;  // light travelling down inside, after n round trips
    for (int n = 0; n < orders; ++n) {
        slab.transmission += leaveBottom * afterEntering;
        slab.reflection += leaveTop * (insideBottom * afterEntering);
        afterEntering = insideTop * (insideBottom * afterEntering);
    }
    return slab;
}

SlabMatrices thinSlab(double eta, const Vec3d& in) {
    const ThinDielectricBxdf<Spec> thin{Spec(eta)};
    const Vec3d reflected(in.x, in.y, -in.z);
    // Under total internal reflection at the first boundary (eta < 1) nothing is transmitted
    // and the slab has no transmission lobe to sample.
    const bool transmits = thin.reflectance(in.z)[0] < 1.0;
    const Mueller none = Mueller::diagonal(Spec(0.0), Spec(0.0), Spec(0.0), Spec(0.0));
    return {deltaMueller(thin, in, reflected), transmits ? deltaMueller(thin, in, in) : none};
}

void expectNear(const Mueller& a, const Mueller& b, double tolerance, const std::string& where) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            ASSERT_NEAR(a(r, c)[0], b(r, c)[0], tolerance) << where << " element " << r << c;
}

TEST(PolarisedThinDielectric, IsTheSlabOfTwoPolarisingBoundariesBuiltEventByEvent) {
    for (const double eta : {1.5, 1.33, 2.42}) {
        const double brewster = std::atan(eta) * 180.0 / std::numbers::pi;
        for (const double theta : {0.0, 10.0, 30.0, 45.0, brewster, 70.0, 85.0, 89.0}) {
            const Vec3d wo = fromAngle(theta);
            const Vec3d in(wo.x, wo.y, -wo.z);
            const SlabMatrices expected = eventByEvent(eta, in, 400);
            const SlabMatrices slab = thinSlab(eta, in);
            const std::string where =
                "eta " + std::to_string(eta) + " theta " + std::to_string(theta);
            expectNear(slab.reflection, expected.reflection, 1e-12, where + " reflection");
            expectNear(slab.transmission, expected.transmission, 1e-12, where + " transmission");
        }
    }
}

TEST(PolarisedThinDielectric, EveryPolarisationIsReflectedOrTransmittedWithoutLoss) {
    for (const double eta : {1.5, 1.33, 2.42, 1.0 / 1.5}) {
        for (double theta = 0.0; theta < 90.0; theta += 2.5) {
            const Vec3d wo = fromAngle(theta, 1.1);
            const Vec3d in(wo.x, wo.y, -wo.z);
            const SlabMatrices slab = thinSlab(eta, in);
            // S0 leaving is frame-free: row 0 of both matrices must add up to (1, 0, 0, 0).
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(slab.reflection(0, c)[0] + slab.transmission(0, c)[0],
                            c == 0 ? 1.0 : 0.0, 1e-12)
                    << "eta " << eta << " theta " << theta << " column " << c;
        }
    }
}

TEST(PolarisedThinDielectric, NormalIncidenceIsTheUnpolarisedSlab) {
    // R = 0.04, R' = 2R / (1 + R); reflection is a half-wave retarder there, as one boundary's.
    const SlabMatrices slab = thinSlab(1.5, {0.0, 0.0, -1.0});
    const double r = 2 * 0.04 / 1.04;
    expectNear(slab.reflection, Mueller::diagonal(Spec(r), Spec(r), Spec(-r), Spec(-r)), 1e-15,
               "reflection");
    expectNear(slab.transmission,
               Mueller::diagonal(Spec(1 - r), Spec(1 - r), Spec(1 - r), Spec(1 - r)), 1e-15,
               "transmission");
}

TEST(PolarisedThinDielectric, AtBrewstersAngleItIsAOnePlatePolariser) {
    // R_p = 0 at tan(theta) = eta; R_s = ((eta^2 - 1) / (eta^2 + 1))^2 = 0.147929 for 1.5.
    const double eta = 1.5, rs = std::pow((eta * eta - 1) / (eta * eta + 1), 2);
    const Vec3d wo = fromAngle(std::atan(eta) * 180.0 / std::numbers::pi);
    const SlabMatrices slab = thinSlab(eta, {wo.x, wo.y, -wo.z});
    const StokesVector<double> unpolarised{1.0, 0.0, 0.0, 0.0};
    auto apply = [&](const Mueller& m) {
        StokesVector<double> out{};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                out[r] += m(r, c)[0] * unpolarised[c];
        return out;
    };
    auto dolp = [](const StokesVector<double>& s) { return std::hypot(s[1], s[2]) / s[0]; };
    const StokesVector<double> reflected = apply(slab.reflection);
    const StokesVector<double> transmitted = apply(slab.transmission);
    // Only s is reflected, by the series 2 R_s / (1 + R_s), half of unpolarised light's power.
    EXPECT_NEAR(reflected[0], 0.5 * 2 * rs / (1 + rs), 1e-6);
    EXPECT_NEAR(dolp(reflected), 1.0, 1e-6);
    // Transmitted: p whole, s by (1 - R_s) / (1 + R_s), so the degree of polarisation is R_s.
    EXPECT_NEAR(transmitted[0], 0.5 * (1 + (1 - rs) / (1 + rs)), 1e-6);
    EXPECT_NEAR(dolp(transmitted), rs, 1e-6);
    // The unpolarised slab's R' = 2R / (1 + R) of the averaged R = R_s / 2 is larger.
    const ThinDielectricBxdf<Spec> thin{Spec(eta)};
    EXPECT_GT(thin.reflectance(wo.z)[0], reflected[0] + 0.005);
}

}  // namespace
}  // namespace lamina
