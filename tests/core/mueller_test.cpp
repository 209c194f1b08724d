// Closed-form facts of lamina's Stokes/Mueller convention (core/stokes.h, mueller_matrix.h,
// fresnel_amplitudes.h), in float and double: the element matrices, the frame rotation, the
// Fresnel matrices at the angles where optics textbooks give their values (Born and Wolf,
// "Principles of Optics", 7th ed., sections 1.5.2-1.5.4), and two mirrors in 3D whose result
// depends on the frames turning between the reflections.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "lamina/core/fresnel_amplitudes.h"
#include "lamina/core/mueller_matrix.h"

namespace lamina {
namespace {

template <typename T>
class MuellerTest : public ::testing::Test {
  protected:
    static constexpr T kPi = std::numbers::pi_v<T>;
    // Relative tolerances of a few ulps after the handful of operations each value takes.
    static constexpr T kTolerance = std::is_same_v<T, float> ? T(2e-6) : T(1e-13);

    static void expectMatrixNear(const MuellerMatrix<T>& a, const MuellerMatrix<T>& b, T scale) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                EXPECT_NEAR(a(i, j), b(i, j), kTolerance * 4 * scale) << "element " << i << j;
    }
    static void expectStokesNear(const StokesVector<T>& a, const StokesVector<T>& b) {
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(a[i], b[i], kTolerance * 4) << "S" << i;
    }
    static MuellerMatrix<T> reflection(T cosTheta, std::complex<T> eta) {
        return fresnelReflectionMueller(fresnelAmplitudes(cosTheta, eta));
    }
};

using FloatTypes = ::testing::Types<float, double>;
TYPED_TEST_SUITE(MuellerTest, FloatTypes);

TYPED_TEST(MuellerTest, ADepolariserLeavesUnpolarisedLightOfItsAlbedo) {
    using T = TypeParam;
    const StokesVector<T> fullyPolarised{T(1), T(0.6), T(-0.64), T(0.48)};
    const StokesVector<T> out = depolarising(T(0.7)) * fullyPolarised;
    this->expectStokesNear(out, unpolarisedStokes(T(0.7)));
    EXPECT_EQ(degreeOfPolarisation(out), T(0));
    EXPECT_NEAR(degreeOfPolarisation(fullyPolarised), T(1), this->kTolerance * 4);
}

TYPED_TEST(MuellerTest, TurningTheFrameByPlusMinus45DegreesMovesXLightToMinusPlusS2) {
    using T = TypeParam;
    const StokesVector<T> alongX{T(1), T(1), T(0), T(0)};
    this->expectStokesNear(stokesRotation(this->kPi / 4) * alongX, {T(1), T(0), T(-1), T(0)});
    this->expectStokesNear(stokesRotation(-this->kPi / 4) * alongX, {T(1), T(0), T(1), T(0)});
    // The same through the 3D frames: the ray along +z with x = (1,0,0); the new x axis
    // (1,1,0)/sqrt 2 is a turn of +45 degrees (towards y = d x x = (0,1,0)).
    const StokesFrame<T> frame{Vec3<T>(0, 0, 1), Vec3<T>(1, 0, 0)};
    EXPECT_NEAR(frameTurn(frame, glm::normalize(Vec3<T>(1, 1, 0))), this->kPi / 4,
                this->kTolerance * 4);
    this->expectStokesNear(stokesRotation(frame, glm::normalize(Vec3<T>(1, -1, 0))) * alongX,
                           {T(1), T(0), T(1), T(0)});
}

TYPED_TEST(MuellerTest, TheDoubledTurnWithoutTrigonometryIsTheTurnsDoubleAngle) {
    // doubledFrameTurn is the hot path's frameTurn: the same cos(2 phi), sin(2 phi) for new x
    // axes all round the direction, of any length and not quite perpendicular to it (as the
    // frames of two vertices meet), and no turn for an axis with no projection at all.
    using T = TypeParam;
    const Vec3<T> d = glm::normalize(Vec3<T>(T(0.3), T(-0.5), T(0.8)));
    const StokesFrame<T> frame{d, stokesAxis(d)};
    for (int degrees = -180; degrees < 180; degrees += 7) {
        const T phi = T(degrees) * this->kPi / 180;
        const Vec3<T> x = std::cos(phi) * frame.x + std::sin(phi) * frame.y();
        const Vec3<T> toX = T(2.5) * x + T(1e-3) * d;
        const DoubledTurn<T> turn = doubledFrameTurn(frame, toX);
        const T angle = frameTurn(frame, toX);
        EXPECT_NEAR(turn.c, std::cos(2 * angle), this->kTolerance * 4) << degrees;
        EXPECT_NEAR(turn.s, std::sin(2 * angle), this->kTolerance * 4) << degrees;
        EXPECT_NEAR(turn.c, std::cos(2 * phi), this->kTolerance * 8) << degrees;
    }
    const DoubledTurn<T> none = doubledFrameTurn(frame, Vec3<T>(0));
    EXPECT_EQ(none.c, T(1));
    EXPECT_EQ(none.s, T(0));
}

TYPED_TEST(MuellerTest, MalussLawThroughTwoPolarisers) {
    using T = TypeParam;
    for (int degrees = 0; degrees <= 180; degrees += 15) {
        const T angle = T(degrees) * this->kPi / 180;
        const StokesVector<T> out =
            linearPolariser(angle + T(0.3)) * (linearPolariser(T(0.3)) * unpolarisedStokes(T(1)));
        EXPECT_NEAR(out[0], T(0.5) * std::pow(std::cos(angle), T(2)), this->kTolerance * 4)
            << degrees << " degrees";
    }
}

TYPED_TEST(MuellerTest, ARotatedPolariserEqualsItsClosedForm) {
    using T = TypeParam;
    const MuellerMatrix<T> alongX = amplitudeMueller(std::complex<T>(T(1)), std::complex<T>(T(0)));
    for (const T theta : {T(0.1), T(0.7), T(-1.2), T(2.5)})
        this->expectMatrixNear(rotatedElement(alongX, theta), linearPolariser(theta), T(1));
}

TYPED_TEST(MuellerTest, AQuarterWaveRetarderAt45DegreesMakesXLightCircular) {
    using T = TypeParam;
    // Fast axis at 45 degrees, x light splits equally between fast and slow axes; the slow one
    // lags a quarter wave. In the retarder's frame that light is -S2 (see the rotation test);
    // a lag of pi/2 turns S2 into S3 (S3' = sin(delta) S2), so it leaves with S3 = -1.
    const StokesVector<T> out =
        linearRetarder(this->kPi / 4, this->kPi / 2) * StokesVector<T>{T(1), T(1), T(0), T(0)};
    this->expectStokesNear(out, {T(1), T(0), T(0), T(-1)});
}

TYPED_TEST(MuellerTest, DielectricReflectionAtNormalIncidenceIsFourPercentOfAHalfWaveRetarder) {
    using T = TypeParam;
    const MuellerMatrix<T> m = this->reflection(T(1), std::complex<T>(T(1.5)));
    this->expectMatrixNear(m, linearRetarder(T(0), this->kPi) * T(0.04), T(0.04));
    EXPECT_NEAR(m(0, 0), fresnelDielectric(T(1), T(1.5)), this->kTolerance * 4);
}

TYPED_TEST(MuellerTest, BrewstersAngleReflectsOnlyS) {
    using T = TypeParam;
    const T eta = T(1.5);
    const T brewster = std::atan(eta);
    const MuellerMatrix<T> m = this->reflection(std::cos(brewster), std::complex<T>(eta));
    // r_p = 0: the upper-left block is |r_s|^2 / 2 in every element, with |r_s| =
    // sin(theta_i - theta_t) and theta_t = pi/2 - theta_i at Brewster's angle.
    const T expected = T(0.0739644970414201);  // (5/13)^2 / 2 for eta = 1.5
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            EXPECT_NEAR(m(i, j), expected, T(8) * this->kTolerance);
    EXPECT_NEAR(m(2, 2), T(0), T(8) * this->kTolerance);
    // r_p changes sign through Brewster's angle, so M22 = M33 = Re(r_s conj(r_p)) does.
    const MuellerMatrix<T> below = this->reflection(std::cos(brewster - T(0.05)), eta);
    const MuellerMatrix<T> above = this->reflection(std::cos(brewster + T(0.05)), eta);
    EXPECT_LT(below(2, 2), T(0));
    EXPECT_LT(below(3, 3), T(0));
    EXPECT_GT(above(2, 2), T(0));
    EXPECT_GT(above(3, 3), T(0));
}

TYPED_TEST(MuellerTest, TotalInternalReflectionRetardsMostAtItsClosedFormAngle) {
    using T = TypeParam;
    const T eta = T(1) / T(1.5);  // from inside glass
    // Born and Wolf 1.5.4, eq. (64)-(65): the phase difference under total internal
    // reflection peaks at cos^2 = (1 - eta^2) / (1 + eta^2) with tan(delta / 2) =
    // (1 - eta^2) / (2 eta).
    const T peakCos = std::sqrt((T(1) - eta * eta) / (T(1) + eta * eta));
    const T peakDelta = T(2) * std::atan((T(1) - eta * eta) / (T(2) * eta));
    const auto retardance = [&](T cosTheta) {
        const MuellerMatrix<T> m = this->reflection(cosTheta, std::complex<T>(eta));
        EXPECT_NEAR(m(0, 0), T(1), this->kTolerance * 8);  // total: nothing transmitted
        return std::atan2(m(2, 3), m(2, 2));
    };
    EXPECT_NEAR(retardance(peakCos), peakDelta, T(20) * this->kTolerance);
    for (const T offset : {T(-0.02), T(0.02)})
        EXPECT_LT(retardance(peakCos + offset), peakDelta);
}

TYPED_TEST(MuellerTest, GrazingIncidenceIsTheIdentity) {
    using T = TypeParam;
    for (const std::complex<T> eta : {std::complex<T>(1.5), std::complex<T>(T(0.47), T(2.4))})
        this->expectMatrixNear(this->reflection(T(0), eta), MuellerMatrix<T>::identity(), T(1));
}

TYPED_TEST(MuellerTest, ALosslessInterfaceConservesPowerInSAndP) {
    using T = TypeParam;
    for (const T eta : {T(1.5), T(1) / T(1.5), T(2.4)})
        for (const T cosTheta : {T(0.05), T(0.3), T(0.7), T(1)}) {
            const FresnelAmplitudes<T> f = fresnelAmplitudes(cosTheta, std::complex<T>(eta));
            const T total = fresnelReflectionMueller(f)(0, 0) + fresnelTransmissionMueller(f)(0, 0);
            EXPECT_NEAR(total, T(1), T(16) * this->kTolerance) << eta << " " << cosTheta;
            // And each polarisation separately: the (0,1) elements cancel too.
            const T diattenuation =
                fresnelReflectionMueller(f)(0, 1) + fresnelTransmissionMueller(f)(0, 1);
            EXPECT_NEAR(diattenuation, T(0), T(16) * this->kTolerance);
        }
}

TYPED_TEST(MuellerTest, GoldsRetardanceMatchesTheAngleForm) {
    using T = TypeParam;
    // Gold at 550 nm (Johnson and Christy 1972, Phys. Rev. B 6, 4370: n = 0.43, k = 2.455 at
    // 2.25 eV); any absorbing index would do, the check is the algebra. The independent route:
    // r_p / r_s = -cos(theta_i + theta_t) / cos(theta_i - theta_t) with the complex
    // refraction angle from Snell's law (Born and Wolf 1.5 eq. 21 and 14.2).
    const std::complex<T> eta(T(0.43), T(2.455));
    for (const T degrees : {T(20), T(45), T(70), T(85)}) {
        const T thetaI = degrees * this->kPi / 180;
        const std::complex<T> thetaT = std::asin(std::complex<T>(std::sin(thetaI)) / eta);
        const std::complex<T> ratio = -std::cos(thetaI + thetaT) / std::cos(thetaI - thetaT);
        const MuellerMatrix<T> m = this->reflection(std::cos(thetaI), eta);
        // M22 + i M23 = r_s conj(r_p) = |r_s|^2 conj(r_p / r_s).
        const T expectedPhase = -std::arg(ratio);
        EXPECT_NEAR(std::atan2(m(2, 3), m(2, 2)), expectedPhase, T(50) * this->kTolerance)
            << degrees << " degrees";
        const T rs2 = m(0, 0) + m(0, 1);  // |r_s|^2
        EXPECT_NEAR(std::hypot(m(2, 2), m(2, 3)), rs2 * std::abs(ratio), T(50) * this->kTolerance);
        EXPECT_NEAR(m(0, 0), fresnelConductor(std::cos(thetaI), eta.real(), eta.imag()),
                    T(20) * this->kTolerance);
    }
}

TYPED_TEST(MuellerTest, StokesAxesAndShadingFramesAreRightHanded) {
    using T = TypeParam;
    // The polarised mode measures frame turns in world space for matrices a BSDF wrote in its
    // shading frame: that is the same turn only if the frame does not mirror.
    for (const Vec3<T> n :
         {Vec3<T>(0, 0, 1), Vec3<T>(0, 0, -1), Vec3<T>(0, -1, 0),
          glm::normalize(Vec3<T>(1, -2, 0.5)), glm::normalize(Vec3<T>(-3, 1, -2))}) {
        const Frame<T> f = Frame<T>::fromNormal(n);
        const Vec3<T> c = glm::cross(f.s, f.t);
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(c[i], n[i], this->kTolerance * 4);
        EXPECT_NEAR(glm::dot(stokesAxis(n), n), T(0), this->kTolerance * 4);
    }
}

/// Q M^T Q with Q = diag(1, 1, -1, 1): the matrix of the reversed event (docs/polarisation.md,
/// "Reciprocity").
template <typename T>
MuellerMatrix<T> reversed(const MuellerMatrix<T>& m) {
    const MuellerMatrix<T> q = MuellerMatrix<T>::diagonal(T(1), T(1), T(-1), T(1));
    return q * m.transposed() * q;
}

TYPED_TEST(MuellerTest, FresnelEventsRunBackwardsGiveTheReciprocalMatrix) {
    using T = TypeParam;
    for (const std::complex<T> eta :
         {std::complex<T>(1.5), std::complex<T>(T(1) / T(1.5)), std::complex<T>(T(0.43), T(2.455))})
        for (const T cosI : {T(0.15), T(0.5), T(0.95)}) {
            const FresnelAmplitudes<T> forward = fresnelAmplitudes(cosI, eta);
            const MuellerMatrix<T> r = fresnelReflectionMueller(forward);
            this->expectMatrixNear(reversed(r), r, T(1));
            if (eta.imag() != T(0) || forward.transmittedPowerFactor == T(0)) continue;
            // The transmitted ray run backwards arrives from side 2 at cos_t.
            const T sin2T = (T(1) - cosI * cosI) / (eta.real() * eta.real());
            const T cosT = std::sqrt(T(1) - sin2T);
            const MuellerMatrix<T> back =
                fresnelTransmissionMueller(fresnelAmplitudes(cosT, T(1) / eta));
            this->expectMatrixNear(reversed(back), fresnelTransmissionMueller(forward), T(4));
        }
    // A retarder is reciprocal too, and the check is not vacuous: it has M23 = -M32 != 0.
    const MuellerMatrix<T> quarterWave = linearRetarder(T(0), this->kPi / 2);
    this->expectMatrixNear(reversed(quarterWave), quarterWave, T(1));
    EXPECT_NE(quarterWave(2, 3), T(0));
    EXPECT_GT(std::abs(quarterWave.transposed()(2, 3) - quarterWave(2, 3)), T(1));
}

/// Two mirrors at incidence angle `theta`, the second plane of incidence turned by `turn`
/// about the ray between them: the light's S0 after both, for unpolarised light before.
template <typename T>
T twoMirrors(T theta, T turn, std::complex<T> eta) {
    const Vec3<T> d0(0, 0, -1);
    const Vec3<T> n1(std::sin(theta), 0, std::cos(theta));
    const Vec3<T> d1 = d0 - n1 * (T(2) * glm::dot(d0, n1));
    // The second normal: at theta to -d1, tilted in the plane turned by `turn` about d1.
    const Vec3<T> u0 = glm::normalize(glm::cross(d1, Vec3<T>(0, 1, 0)));
    const Vec3<T> v0 = glm::cross(d1, u0);
    const Vec3<T> u = u0 * std::cos(turn) + v0 * std::sin(turn);
    const Vec3<T> n2 = -d1 * std::cos(theta) + u * std::sin(theta);
    const Vec3<T> fallback(1, 0, 0);
    StokesVector<T> light = unpolarisedStokes(T(1));
    StokesFrame<T> frame{d0, Vec3<T>(1, 0, 0)};
    for (const Vec3<T>& n : {n1, n2}) {
        const Vec3<T> s = planeOfIncidenceNormal(frame.d, n, fallback);
        light = stokesRotation(frame, s) * light;
        const T cosTheta = -glm::dot(frame.d, n);
        light = fresnelReflectionMueller(fresnelAmplitudes(cosTheta, eta)) * light;
        frame = {frame.d - n * (T(2) * glm::dot(frame.d, n)), s};
    }
    return light[0];
}

TYPED_TEST(MuellerTest, TwoMirrorsReflectRsRpCrossedAndTheMeanSquareParallel) {
    using T = TypeParam;
    for (const std::complex<T> eta : {std::complex<T>(1.5), std::complex<T>(T(0.43), T(2.455))})
        for (const T theta : {std::atan(T(1.5)), T(0.9), T(0.3)}) {
            const FresnelAmplitudes<T> f = fresnelAmplitudes(std::cos(theta), eta);
            const T rs = std::norm(f.rs), rp = std::norm(f.rp);
            EXPECT_NEAR(twoMirrors(theta, T(0), eta), T(0.5) * (rs * rs + rp * rp),
                        T(20) * this->kTolerance);
            EXPECT_NEAR(twoMirrors(theta, this->kPi / 2, eta), rs * rp, T(20) * this->kTolerance);
            EXPECT_NEAR(twoMirrors(theta, this->kPi, eta), T(0.5) * (rs * rs + rp * rp),
                        T(20) * this->kTolerance);
        }
    // At Brewster's angle crossed dielectric mirrors pass nothing, where a renderer that
    // averages s and p at each event gives ((Rs + Rp) / 2)^2, visibly not 0.
    EXPECT_NEAR(twoMirrors(std::atan(T(1.5)), this->kPi / 2, std::complex<T>(1.5)), T(0),
                this->kTolerance);
}

}  // namespace
}  // namespace lamina
