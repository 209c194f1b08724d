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

/// The principal square root of a complex number (real part >= 0), without the library
/// call: sqrt(x + i y) = a + i b with a = sqrt((|z| + x) / 2), b = y / (2 a) for x >= 0, and
/// the roles swapped for x < 0 so that neither half cancels. Always inlined: since the thin
/// film and the Fresnel amplitudes call it too, GCC 12 stopped inlining it into
/// fresnelConductor, and the call cost about 5% of a spectral render of metals (perf, veach-mis).
template <std::floating_point T>
[[gnu::always_inline]] inline std::complex<T> principalSqrt(const std::complex<T>& z) {
    const T x = z.real(), y = z.imag();
    const T r = std::sqrt(x * x + y * y);
    if (r == T(0)) return {T(0), T(0)};
    if (x >= T(0)) {
        const T a = std::sqrt(T(0.5) * (r + x));
        return {a, y / (T(2) * a)};
    }
    const T b = std::copysign(std::sqrt(T(0.5) * (r - x)), y);
    return {y / (T(2) * b), b};
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
    // Only |r|^2 is needed, and |a / b|^2 = |a|^2 / |b|^2: no complex division (libgcc's
    // __divsc3, with its C99 infinity handling, was a third of the cost in spectral renders).
    const C n2 = n * n;
    const C sin2ThetaT = std::conj(n2) * (sin2ThetaI / std::norm(n2));
    const C cosThetaT = principalSqrt(C(1) - sin2ThetaT);
    const C nCosI = n * cosThetaI, nCosT = n * cosThetaT;
    const T rParallel2 = std::norm(nCosI - cosThetaT) / std::norm(nCosI + cosThetaT);
    const T rPerpendicular2 = std::norm(cosThetaI - nCosT) / std::norm(cosThetaI + nCosT);
    const T r = T(0.5) * (rParallel2 + rPerpendicular2);
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
