// The polarised variant of every BSDF in the catalogue (evalMueller, sampleMueller;
// docs/polarisation.md): the [0][0] element is the unpolarised value, each channel's matrix is
// physically realisable (no polarised input leaves with more polarisation than radiance), and
// the Mueller reciprocity relation M_reverse = Q M^T Q holds between (wo, wi) and (wi, wo)
// once both are written in the same frames. Plus the delta lobes' closed forms.
#include <gtest/gtest.h>

#include <numbers>

#include "bsdf_cases.h"
#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/optical_sheet.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

using testing::Spec;
using Mueller = MuellerMatrix<Spec>;

class PolarisedBsdf : public ::testing::TestWithParam<testing::BsdfCase> {};

Vec3d randomDirection(Pcg32& rng) {
    const double z = 2.0 * rng.nextDouble() - 1.0;
    const double phi = 2.0 * std::numbers::pi * rng.nextDouble();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Channel c of a spectral Mueller matrix.
MuellerMatrix<double> channel(const Mueller& m, int c) {
    MuellerMatrix<double> r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r(i, j) = m(i, j)[c];
    return r;
}

/// Every pure polarisation state maps to a state with S0 >= |(S1, S2, S3)|.
void expectRealisable(MuellerMatrix<double> m, const std::string& where) {
    // Scaled to [0][0] = 1 first: the squares of a far tail's values would underflow.
    if (m(0, 0) > 0.0) m *= 1.0 / m(0, 0);
    const double norm = 1.0;
    for (int axis = 1; axis < 4; ++axis)
        for (double sign : {1.0, -1.0}) {
            StokesVector<double> in{1.0, 0.0, 0.0, 0.0};
            in[axis] = sign;
            const StokesVector<double> out = m * in;
            const double polarised = std::sqrt(out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
            EXPECT_GE(out[0] - polarised, -1e-9 * norm) << where << " input S" << axis << sign;
        }
}

TEST_P(PolarisedBsdf, ItsFirstElementIsTheUnpolarisedValueAndItIsRealisable) {
    const Bxdf<Spec>& bxdf = *GetParam().bxdf;
    Pcg32 rng(5);
    int nonzero = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3d wo = randomDirection(rng), wi = randomDirection(rng);
        const Spec f = bxdf.eval(wo, wi, TransportMode::Radiance);
        const Mueller m = bxdf.evalMueller(wo, wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(m(0, 0)[c], f[c], 1e-12 * std::max(1.0, std::abs(f[c])));
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k)
                    ASSERT_TRUE(std::isfinite(m(r, k)[c]));
            expectRealisable(channel(m, c), "eval");
        }
        nonzero += f.maxValue() > 0.0;
        const auto s = bxdf.sample(wo, rng.nextDouble(), {rng.nextDouble(), rng.nextDouble()},
                                   TransportMode::Radiance);
        if (!s) continue;
        const Mueller w = bxdf.sampleMueller(wo, *s, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(w(0, 0)[c], s->weight[c], 1e-9 * std::max(1.0, s->weight[c]));
            expectRealisable(channel(w, c), "sample");
        }
    }
    EXPECT_GT(nonzero, 20) << "too few pairs with a value to test anything";
}

/// m written for output frame `outAxis` instead of stokesAxis(outDir), input `inAxis` instead
/// of stokesAxis(inDir).
Mueller reframed(Mueller m, const Vec3d& inDir, const Vec3d& inAxis, const Vec3d& outDir,
                 const Vec3d& outAxis) {
    // The light arrives in frame inAxis: turn it into the canonical frame the matrix expects.
    turnInputFrame(m, frameTurn(StokesFrame<double>{inDir, inAxis}, stokesAxis(inDir)));
    turnOutputFrame(m, frameTurn(StokesFrame<double>{outDir, stokesAxis(outDir)}, outAxis));
    return m;
}

TEST_P(PolarisedBsdf, RunningTheLightBackwardsGivesTheReciprocalMatrix) {
    const Bxdf<Spec>& bxdf = *GetParam().bxdf;
    Pcg32 rng(9);
    int checked = 0;
    const Mueller q = Mueller::diagonal(Spec(1.0), Spec(1.0), Spec(-1.0), Spec(1.0));
    for (int i = 0; i < 400; ++i) {
        const Vec3d wo = randomDirection(rng), wi = randomDirection(rng);
        // Forward: light along -wi, out along wo. Backward: along -wo, out along wi. Write both
        // with the forward matrix's x lines: x_a for the wi line, x_b for the wo line.
        const Vec3d xa = stokesAxis(-wi), xb = stokesAxis(wo);
        const Mueller forward = bxdf.evalMueller(wo, wi, TransportMode::Importance);
        const Mueller backward =
            reframed(bxdf.evalMueller(wi, wo, TransportMode::Importance), -wo, xb, wi, xa);
        const Mueller expected = q * forward.transposed() * q;
        for (int c = 0; c < 3; ++c) {
            // eval carries |cos theta_i| of its own wi: compare the matrices per unit [0][0].
            const double a = expected(0, 0)[c], b = backward(0, 0)[c];
            if (!(a > 1e-8) || !(b > 1e-8)) continue;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k)
                    ASSERT_NEAR(backward(r, k)[c] / b, expected(r, k)[c] / a, 1e-7)
                        << "element " << r << k << " channel " << c;
            ++checked;
        }
    }
    EXPECT_GT(checked, 20) << "too few pairs with a value to test anything";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, PolarisedBsdf, ::testing::ValuesIn(testing::bsdfCases()),
                         [](const auto& test) { return test.param.name; });

TEST(PolarisedDeltaLobes, GlassAtNormalIncidenceReflectsFourPercentOfAHalfWaveRetarder) {
    const DielectricBxdf<Spec> glass(1.5, MicrofacetDistribution<double>(NdfKind::Ggx, 0.0, 0.0));
    const Vec3d wo(0.0, 0.0, 1.0);
    const auto reflected = glass.sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(reflected && reflected->isSpecular() && !reflected->isTransmission());
    // The weight is F / P(reflection) = 1; the matrix over it is diag(1, 1, -1, -1).
    const Mueller m = glass.sampleMueller(wo, *reflected, TransportMode::Radiance);
    const Mueller expected = Mueller::diagonal(Spec(1.0), Spec(1.0), Spec(-1.0), Spec(-1.0));
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(m(r, k)[c], expected(r, k)[c], 1e-12);
}

TEST(PolarisedDeltaLobes, GlassAtBrewstersAngleReflectsOnlyS) {
    const DielectricBxdf<Spec> glass(1.5, MicrofacetDistribution<double>(NdfKind::Ggx, 0.0, 0.0));
    const double brewster = std::atan(1.5);
    const Vec3d wo(std::sin(brewster), 0.0, std::cos(brewster));
    const auto reflected = glass.sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(reflected && !reflected->isTransmission());
    const Mueller m = glass.sampleMueller(wo, *reflected, TransportMode::Radiance);
    // Fully polarised: unpolarised light leaves with S1^2 + S2^2 = S0^2 (whatever the frame).
    const double s0 = m(0, 0)[0], s1 = m(1, 0)[0], s2 = m(2, 0)[0];
    EXPECT_NEAR(std::hypot(s1, s2), s0, 1e-9);
    // And the refracted light is partly polarised the other way, less than fully.
    const auto refracted = glass.sample(wo, 0.99, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(refracted && refracted->isTransmission());
    const Mueller t = glass.sampleMueller(wo, *refracted, TransportMode::Radiance);
    const double dolp = std::hypot(t(1, 0)[0], t(2, 0)[0]) / t(0, 0)[0];
    EXPECT_GT(dolp, 0.05);
    EXPECT_LT(dolp, 0.2);
}

TEST(PolarisedDeltaLobes, TotalInternalReflectionInsideGlassRetardsByTheClosedForm) {
    const DielectricBxdf<Spec> glass(1.5, MicrofacetDistribution<double>(NdfKind::Ggx, 0.0, 0.0));
    const double theta = std::numbers::pi / 3.0;  // beyond the critical angle, 41.8 degrees
    const Vec3d wo(std::sin(theta), 0.0, -std::cos(theta));  // inside
    const auto s = glass.sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s && !s->isTransmission());
    const Mueller m = glass.sampleMueller(wo, *s, TransportMode::Radiance);
    // Born and Wolf 1.5.4, eq. (62): tan(delta / 2) = cos(theta) sqrt(sin^2 - n^2) / sin^2
    // with n = 1 / 1.5. M33 = cos(delta) whatever the frames (they turn S1 and S2 only).
    const double n = 1.0 / 1.5, sin2 = std::pow(std::sin(theta), 2.0);
    const double delta = 2.0 * std::atan(std::cos(theta) * std::sqrt(sin2 - n * n) / sin2);
    EXPECT_NEAR(m(0, 0)[0], 1.0, 1e-12);
    EXPECT_NEAR(m(3, 3)[0], std::cos(delta), 1e-12);
}

TEST(PolarisedDeltaLobes, ASmoothConductorRetardsAndItsFirstElementIsFresnel) {
    const ConductorBxdf<Spec> gold(MicrofacetReflectionLobe<Spec>(
        MicrofacetDistribution<double>(NdfKind::Ggx, 0.0, 0.0), testing::goldFresnel()));
    const Vec3d wo = testing::directionAt(60.0);
    const auto s = gold.sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s && s->isSpecular());
    const Mueller m = gold.sampleMueller(wo, *s, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(m(0, 0)[c], s->weight[c], 1e-12);
        // A conductor's reflection turns linear into elliptical light: S3 from S2 input, in
        // any frame (the frame turn leaves S3 alone and spreads S2 over S1 and S2).
        const double circular = std::hypot(m(3, 1)[c], m(3, 2)[c]);
        EXPECT_GT(circular, 0.05 * m(0, 0)[c]) << "channel " << c;
    }
}

// The optical sheets (optical_sheet.h): at normal incidence the frame of the light along +z
// has x = (1, 0, 0) and y = (0, 1, 0) (stokesAxis), so a sheet whose axis is at theta in the
// shading plane is the element at theta: linearPolariser(theta) times its transmittance, and
// linearRetarder(theta, delta). Straight through, with [0][0] the unpolarised weight (T / 2
// and 1). Running the light backwards through either gives the reciprocal matrix Q M^T Q in
// the forward frames' x lines, at oblique incidence too.
OpticalSheetBxdf<Spec> sheet(bool polariser, double theta) {
    const Vec3d axis(std::cos(theta), std::sin(theta), 0.0);
    using Element = OpticalSheetBxdf<Spec>::Element;
    return polariser ? OpticalSheetBxdf<Spec>(Element::Polariser, axis, 0.8, 0.0)
                     : OpticalSheetBxdf<Spec>(Element::Retarder, axis, 1.0, std::numbers::pi / 3);
}

TEST(PolarisedOpticalSheets, AtNormalIncidenceTheyAreTheirClosedFormsAtTheirAxesAngle) {
    for (const bool polariser : {true, false})
        for (const double theta : {0.0, 0.3, 1.2, -0.7, 2.0}) {
            const auto bxdf = sheet(polariser, theta);
            const Vec3d wo(0.0, 0.0, 1.0);
            const auto s = bxdf.sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
            ASSERT_TRUE(s && s->isSpecular() && s->isTransmission());
            EXPECT_EQ(s->wi, -wo);
            EXPECT_NEAR(s->weight[1], polariser ? 0.4 : 1.0, 1e-12);
            const Mueller m = bxdf.sampleMueller(wo, *s, TransportMode::Radiance);
            const MuellerMatrix<double> expected =
                polariser ? linearPolariser(theta) * 0.8
                          : linearRetarder(theta, std::numbers::pi / 3);
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k)
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(m(r, k)[c], expected(r, k), 1e-12)
                            << (polariser ? "polariser" : "retarder") << " at " << theta
                            << ", element " << r << k;
        }
}

TEST(PolarisedOpticalSheets, RunningTheLightBackwardsGivesTheReciprocalMatrix) {
    const Mueller q = Mueller::diagonal(Spec(1.0), Spec(1.0), Spec(-1.0), Spec(1.0));
    Pcg32 rng(4);
    for (const bool polariser : {true, false})
        for (int i = 0; i < 50; ++i) {
            const auto bxdf = sheet(polariser, 3.0 * rng.nextDouble());
            Vec3d wo = randomDirection(rng);
            if (std::abs(wo.z) < 0.05) continue;
            const auto s = bxdf.sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
            ASSERT_TRUE(s);
            const Vec3d wi = s->wi;  // -wo
            const Mueller forward = bxdf.sampleMueller(wo, *s, TransportMode::Radiance);
            const auto back = bxdf.sample(wi, 0.5, {0.5, 0.5}, TransportMode::Radiance);
            ASSERT_TRUE(back);
            const Mueller backward =
                reframed(bxdf.sampleMueller(wi, *back, TransportMode::Radiance), -wo,
                         stokesAxis(wo), wi, stokesAxis(-wi));
            const Mueller expected = q * forward.transposed() * q;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k)
                    EXPECT_NEAR(backward(r, k)[0], expected(r, k)[0], 1e-9)
                        << (polariser ? "polariser" : "retarder") << ", element " << r << k;
        }
}

}  // namespace
}  // namespace lamina
