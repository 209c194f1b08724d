// The scattering of one hair fibre, after Chiang, Bitterli, Tappan and Burley 2016, "A
// Practical and Controllable Hair and Fur Model for Production Path Tracing", with the
// longitudinal function of d'Eon, Francois, Hill, Letteri and Aubry 2011, "An Energy-Conserving
// Hair Reflectance Model". A ray meets a rough dielectric cylinder (index eta, absorption
// sigma_a per unit radius) at the offset h in [-1, 1] across its width; its light leaves in
// lobes p = 0 (R, reflection), 1 (TT), 2 (TRT) and the rest (p >= 3, summed). Per lobe
//   S_p(wo, wi) = M_p(theta_i, theta_o') A_p(theta_o, h) N_p(phi_i - phi_o, h)
// in the fibre frame: x along the fibre (sin theta = x), phi the angle in the y-z plane. The sum
// over p is f(wo, wi) |cos| in lamina's convention: each M_p integrates to 1 over theta_i with
// cos theta_i dtheta_i, each N_p to 1 over phi, and the A_p sum to 1 without absorption, so an
// absorption-free fibre scatters everything (Chiang's white furnace).
//   M_p  d'Eon's longitudinal lobe, a von Mises-Fisher distribution projected on theta:
//        csch(1/v) / (2v) exp(-sin theta_i sin theta_o' / v) I0(cos theta_i cos theta_o' / v),
//        with theta_o' the cuticle tilt alpha applied (-2 alpha for R, alpha for TT, 4 alpha for
//        TRT) and v from beta_m (Chiang's fit, v = (0.726 b + 0.812 b^2 + 3.7 b^20)^2), v/4 for
//        TT and 4v for TRT and beyond.
//   A_p  attenuation: Fresnel reflectance F at cos theta_o cos gamma_o (gamma_o = asin h), the
//        transmittance T = exp(-sigma_a 2 cos gamma_t / cos theta_t) of one chord, and
//        A_0 = F, A_1 = (1-F)^2 T, A_2 = A_1 T F, A_3 = A_2 T F / (1 - T F).
//   N_p  azimuthal lobe: a logistic of scale s (Chiang's fit from beta_n, s = sqrt(pi/8)
//        (0.265 b + 1.194 b^2 + 5.372 b^22)) trimmed to [-pi, pi], centred on the exit angle
//        Phi(p) = 2 p gamma_t - 2 gamma_o + p pi (gamma_t the refracted offset angle, through
//        Bravais' index eta' = sqrt(eta^2 - sin^2 theta_o) / cos theta_o); uniform for p >= 3.
// Sampling draws p by A_p (their channel average), theta_i by d'Eon's exact sampling of the
// von Mises-Fisher lobe and phi by inverting the trimmed logistic; the density is the mixture
// over p, so eval, pdf and the sample's weight agree.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "lamina/core/fresnel_equations.h"
#include "lamina/core/math.h"
#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina {

template <SpectrumType S>
class HairFiber {
  public:
    static constexpr int kLobes = 4;  ///< R, TT, TRT and the remainder

    /// `alphaDegrees`: the cuticle scales' tilt. betaM and betaN are clamped to >= 0.01 (a
    /// smooth fibre is a delta the model does not sample).
    HairFiber(double eta, const S& sigmaA, double betaM, double betaN, double alphaDegrees)
        : eta_(eta), sigmaA_(sigmaA) {
        const double bm = std::clamp(betaM, 0.01, 1.0), bn = std::clamp(betaN, 0.01, 1.0);
        const double v = sqr(0.726 * bm + 0.812 * bm * bm + 3.7 * std::pow(bm, 20));
        variance_ = {v, 0.25 * v, 4 * v, 4 * v};
        scale_ =
            std::sqrt(kPi<double> / 8) * (0.265 * bn + 1.194 * bn * bn + 5.372 * std::pow(bn, 22));
        const double a = alphaDegrees * kPi<double> / 180;
        tilt_ = {-2 * a, a, 4 * a, 0.0};
    }

    /// What a given wo fixes: its angles, the offset h and the refracted ray's terms.
    struct Incidence {
        double sinThetaO, cosThetaO, phiO, gammaO, gammaT;
        S attenuation[kLobes];
        std::array<double, kLobes> lobeProbability;
    };

    /// The offset h of a ray arriving along -wo at a fibre whose surface normal is z: the sine
    /// of the angle between wo and z in the plane across the fibre (0 along the fibre).
    static double offset(const Vec3d& wo) {
        const double r = std::sqrt(wo.y * wo.y + wo.z * wo.z);
        return r > 1e-12 ? std::clamp(-wo.y / r, -1.0, 1.0) : 0.0;
    }

    Incidence incidence(const Vec3d& wo) const {
        Incidence in;
        in.sinThetaO = std::clamp(wo.x, -1.0, 1.0);
        in.cosThetaO = safeSqrt(1 - sqr(in.sinThetaO));
        in.phiO = std::atan2(wo.z, wo.y);
        const double h = offset(wo);
        in.gammaO = std::asin(h);
        const double sinThetaT = in.sinThetaO / eta_;
        const double cosThetaT = safeSqrt(1 - sqr(sinThetaT));
        const double etaPrime =
            in.cosThetaO > 1e-12 ? safeSqrt(sqr(eta_) - sqr(in.sinThetaO)) / in.cosThetaO : 1e12;
        const double sinGammaT = std::clamp(h / etaPrime, -1.0, 1.0);
        in.gammaT = std::asin(sinGammaT);
        const double chord = cosThetaT > 0 ? 2 * std::sqrt(1 - sqr(sinGammaT)) / cosThetaT : 0;
        S transmittance;
        for (int c = 0; c < S::kSize; ++c)
            transmittance[c] = Float(std::exp(-double(sigmaA_[c]) * chord));
        const double f = fresnelDielectric(in.cosThetaO * std::cos(in.gammaO), eta_);
        in.attenuation[0] = S(Float(f));
        in.attenuation[1] = transmittance * Float(sqr(1 - f));
        in.attenuation[2] = in.attenuation[1] * transmittance * Float(f);
        S rest;
        for (int c = 0; c < S::kSize; ++c) {
            const double tf = double(transmittance[c]) * f;
            rest[c] = tf < 1 ? Float(double(in.attenuation[2][c]) * tf / (1 - tf)) : Float(0);
        }
        in.attenuation[3] = rest;
        double sum = 0;
        for (int p = 0; p < kLobes; ++p)
            sum += (in.lobeProbability[std::size_t(p)] = double(in.attenuation[p].average()));
        for (auto& q : in.lobeProbability)
            q = sum > 0 ? q / sum : 0.25;
        return in;
    }

    /// sum_p S_p(wo, wi) (f |cos| in lamina's convention) and, in `density`, the sampling
    /// density of wi: sum_p P(p) M_p N_p.
    S value(const Incidence& in, const Vec3d& wi, double& density) const {
        const double sinThetaI = std::clamp(wi.x, -1.0, 1.0);
        const double cosThetaI = safeSqrt(1 - sqr(sinThetaI));
        const double phi = std::atan2(wi.z, wi.y) - in.phiO;
        S sum(Float(0));
        density = 0;
        for (int p = 0; p < kLobes; ++p) {
            const double m = longitudinal(p, in, sinThetaI, cosThetaI);
            const double n = p < 3 ? azimuthal(phi - exitAngle(p, in)) : 1 / (2 * kPi<double>);
            sum += in.attenuation[p] * Float(m * n);
            density += in.lobeProbability[std::size_t(p)] * m * n;
        }
        return sum;
    }

    /// A direction drawn with the density of value(): `uc` picks the lobe (and is reused for
    /// the azimuth), `u` the longitudinal angle.
    Vec3d sample(const Incidence& in, double uc, const Vec2d& u) const {
        int p = 0;
        for (; p < kLobes - 1; ++p) {
            const double q = in.lobeProbability[std::size_t(p)];
            if (uc < q) {
                uc = std::min(uc / q, 1 - 1e-12);
                break;
            }
            uc -= q;
        }
        if (p == kLobes - 1) {
            const double q = in.lobeProbability[kLobes - 1];
            uc = q > 0 ? std::clamp(uc / q, 0.0, 1 - 1e-12) : 0.5;
        }
        // d'Eon et al. 2011: a direction of the von Mises-Fisher lobe around the mirrored
        // (tilted) theta_o, projected onto theta.
        const double v = variance_[std::size_t(p)];
        const double u0 = std::max(u.x, 1e-300);
        const double cosTheta =
            std::clamp(1 + v * std::log(u0 + (1 - u0) * std::exp(-2 / v)), -1.0, 1.0);
        const double sinTheta = safeSqrt(1 - sqr(cosTheta));
        const double thetaOp = std::asin(in.sinThetaO) + tilt_[std::size_t(p)];
        const double sinThetaI =
            std::clamp(-cosTheta * std::sin(thetaOp) +
                           sinTheta * std::cos(2 * kPi<double> * u.y) * std::abs(std::cos(thetaOp)),
                       -1.0, 1.0);
        const double cosThetaI = safeSqrt(1 - sqr(sinThetaI));
        const double dphi = p < 3 ? exitAngle(p, in) + sampleAzimuthal(uc) : 2 * kPi<double> * uc;
        const double phiI = in.phiO + dphi;
        return Vec3d(sinThetaI, cosThetaI * std::cos(phiI), cosThetaI * std::sin(phiI));
    }

  private:
    using Float = typename S::Float;

    double exitAngle(int p, const Incidence& in) const {
        return 2 * p * in.gammaT - 2 * in.gammaO + p * kPi<double>;
    }

    // M_p: d'Eon et al. 2011's normalised lobe; in logarithms for a narrow lobe (v <= 0.1),
    // where csch(1/v) / (2v) ~ exp(-1/v) / v and I0 overflows.
    double longitudinal(int p, const Incidence& in, double sinThetaI, double cosThetaI) const {
        const double thetaOp = std::asin(in.sinThetaO) + tilt_[std::size_t(p)];
        const double sinThetaOp = std::sin(thetaOp), cosThetaOp = std::abs(std::cos(thetaOp));
        const double v = variance_[std::size_t(p)];
        const double a = cosThetaI * cosThetaOp / v, b = sinThetaI * sinThetaOp / v;
        if (v <= 0.1) return std::exp(logBesselI0(a) - b - 1 / v - std::log(v));
        return std::exp(-b) * std::cyl_bessel_i(0.0, a) / (2 * v * std::sinh(1 / v));
    }

    static double logBesselI0(double x) {
        if (x > 12) return x - 0.5 * std::log(2 * kPi<double> * x) + 1 / (8 * x);
        return std::log(std::cyl_bessel_i(0.0, x));
    }

    double logisticCdf(double x) const { return 1 / (1 + std::exp(-x / scale_)); }

    // N_p: the logistic of scale s trimmed to [-pi, pi], of the angle wrapped into it.
    double azimuthal(double dphi) const {
        dphi = std::remainder(dphi, 2 * kPi<double>);
        const double e = std::exp(-std::abs(dphi) / scale_);
        const double logistic = e / (scale_ * sqr(1 + e));
        return logistic / (logisticCdf(kPi<double>) - logisticCdf(-kPi<double>));
    }

    double sampleAzimuthal(double u) const {
        const double lo = logisticCdf(-kPi<double>), hi = logisticCdf(kPi<double>);
        const double c = std::clamp(lo + u * (hi - lo), 1e-300, 1 - 1e-16);
        return std::clamp(-scale_ * std::log(1 / c - 1), -kPi<double>, kPi<double>);
    }

    double eta_;
    S sigmaA_;
    std::array<double, kLobes> variance_{}, tilt_{};
    double scale_ = 1;
};

}  // namespace lamina
