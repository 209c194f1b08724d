// The complex Fresnel amplitude coefficients r_s, r_p, t_s, t_p of a smooth interface: what
// the polarised mode needs where the unpolarised one only needs |r_s|^2 and |r_p|^2 (see
// fresnel_equations.h). The signs follow lamina's Stokes convention (stokes.h): every ray's
// frame has x = s, the unit normal of the plane of incidence, and y = d x s for its own
// direction d. With those frames the tangential E and H fields' continuity gives (Born and Wolf,
// "Principles of Optics", section 1.5.2, eqs. 20-21, rederived for these frames in
// docs/polarisation.md):
//   r_s = (n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t)   t_s = 2 n1 cos_i / (n1 cos_i + n2 cos_t)
//   r_p = (n2 cos_i - n1 cos_t) / (n2 cos_i + n1 cos_t)   t_p = 2 n1 cos_i / (n2 cos_i + n1 cos_t)
// so that a perfect mirror at normal incidence has r_s = -1, r_p = +1 (E_reflected = -E_incident
// as vectors, while the p axes of the two rays point opposite ways).
// The time dependence is exp(-i omega t): an absorbing medium has the index n + i k, and under
// total internal reflection cos_t = +i sqrt(sin^2_t - 1), the root of a wave decaying away from
// the interface.
#pragma once

#include <complex>

#include "lamina/core/fresnel_equations.h"

namespace lamina {

template <std::floating_point T>
struct FresnelAmplitudes {
    std::complex<T> rs, rp;  ///< reflected over incident amplitude, s and p
    std::complex<T> ts, tp;  ///< transmitted over incident amplitude, s and p
    /// The factor that turns |t|^2 into transmitted power per unit area of the interface:
    /// Re(n2 cos_t) / (n1 cos_i), so that for a lossless interface |r|^2 + factor |t|^2 = 1
    /// in each of s and p. 0 under total internal reflection and for conductors.
    T transmittedPowerFactor = T(0);
};

/// The amplitudes for light arriving at `cosThetaI` (in [0, 1], the side the light comes from)
/// on an interface whose relative index, transmitted side over incident side, is the complex
/// `eta` (n + i k; k = 0 for a dielectric, eta < 1 from the dense side).
template <std::floating_point T>
FresnelAmplitudes<T> fresnelAmplitudes(T cosThetaI, std::complex<T> eta) {
    using C = std::complex<T>;
    cosThetaI = clamp(cosThetaI, T(0), T(1));
    const T sin2ThetaI = T(1) - sqr(cosThetaI);
    // Snell: sin_t = sin_i / eta, cos_t = sqrt(1 - sin_i^2 / eta^2), the principal root (its
    // imaginary part >= 0 for real eta under total internal reflection: the decaying wave).
    // For a real index the argument is formed in real arithmetic: a complex division could
    // leave it a -0 imaginary part, and the root would take the growing wave's branch.
    const C eta2 = eta * eta;
    const C sin2ThetaT = eta.imag() == T(0) ? C(sin2ThetaI / sqr(eta.real()), T(0))
                                            : std::conj(eta2) * (sin2ThetaI / std::norm(eta2));
    const C cosThetaT = principalSqrt(C(1) - sin2ThetaT);
    const C etaCosI = eta * cosThetaI, etaCosT = eta * cosThetaT;
    FresnelAmplitudes<T> a;
    const C sDenominator = C(cosThetaI) + etaCosT;
    const C pDenominator = etaCosI + cosThetaT;
    if (std::norm(sDenominator) == T(0) || std::norm(pDenominator) == T(0)) {
        // Only at grazing incidence on an index-matched boundary (eta = 1, cos_i = 0): the
        // light passes undisturbed.
        a.rs = a.rp = C(0);
        a.ts = a.tp = C(1);
        a.transmittedPowerFactor = T(1);
        return a;
    }
    a.rs = (C(cosThetaI) - etaCosT) / sDenominator;
    a.rp = (etaCosI - cosThetaT) / pDenominator;
    a.ts = C(T(2) * cosThetaI) / sDenominator;
    a.tp = C(T(2) * cosThetaI) / pDenominator;
    const bool absorbing = eta.imag() != T(0);
    const bool totallyReflected = cosThetaT.real() == T(0);
    if (!absorbing && !totallyReflected && cosThetaI > T(0))
        a.transmittedPowerFactor = eta.real() * cosThetaT.real() / cosThetaI;
    return a;
}

}  // namespace lamina
