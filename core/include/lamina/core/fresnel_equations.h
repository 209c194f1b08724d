// The exact Fresnel equations for unpolarised light (Born and Wolf, "Principles of Optics",
// section 1.5.2; for absorbing media section 14.2). Pure math, shared by the BSDF library's
// Fresnel models and the spectral library's RGB reductions of measured n/k data.
#pragma once

#include <complex>

#include "lamina/core/math.h"

namespace lamina {

/// Reflectance of a smooth dielectric boundary. `cosThetaI` is the cosine of the angle of
/// incidence on the side the light comes from (negative: from inside), `eta` the relative
/// index eta_inside / eta_outside. Total internal reflection returns 1.
template <std::floating_point T>
T fresnelDielectric(T cosThetaI, T eta) {
    cosThetaI = clamp(cosThetaI, T(-1), T(1));
    if (cosThetaI < T(0)) {  // arriving from inside: swap the media
        eta = T(1) / eta;
        cosThetaI = -cosThetaI;
    }
    const T sin2ThetaI = T(1) - sqr(cosThetaI);
    const T sin2ThetaT = sin2ThetaI / sqr(eta);
    if (sin2ThetaT >= T(1)) return T(1);
    const T cosThetaT = safeSqrt(T(1) - sin2ThetaT);
    const T rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const T rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return T(0.5) * (sqr(rParallel) + sqr(rPerpendicular));
}

/// Reflectance of a smooth conductor with complex relative index eta + i k, for
/// cos(theta_i) in [0, 1] (the side of the light is irrelevant for an opaque conductor).
/// Snell's law with a complex index gives a complex cos(theta_t); the amplitude
/// coefficients are the dielectric ones with complex arithmetic.
template <std::floating_point T>
T fresnelConductor(T cosThetaI, T eta, T k) {
    using C = std::complex<T>;
    cosThetaI = clamp(std::abs(cosThetaI), T(0), T(1));
    const C n(eta, k);
    const T sin2ThetaI = T(1) - sqr(cosThetaI);
    const C sin2ThetaT = C(sin2ThetaI) / (n * n);
    const C cosThetaT = std::sqrt(C(1) - sin2ThetaT);
    const C rParallel = (n * cosThetaI - cosThetaT) / (n * cosThetaI + cosThetaT);
    const C rPerpendicular = (C(cosThetaI) - n * cosThetaT) / (C(cosThetaI) + n * cosThetaT);
    const T r = T(0.5) * (std::norm(rParallel) + std::norm(rPerpendicular));
    // n = 0 (and k = 0) is not a material: 0/0 above. Report total reflection.
    return std::isfinite(r) ? clamp(r, T(0), T(1)) : T(1);
}

/// Normal-incidence reflectance of a conductor: ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
template <std::floating_point T>
T conductorF0(T eta, T k) {
    return (sqr(eta - T(1)) + sqr(k)) / (sqr(eta + T(1)) + sqr(k));
}

/// Normal-incidence reflectance of a dielectric boundary with relative index eta.
template <std::floating_point T>
T dielectricF0(T eta) {
    return sqr((eta - T(1)) / (eta + T(1)));
}

}  // namespace lamina
