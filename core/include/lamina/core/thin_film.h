// A thin film on an interface: medium 1 (where the light arrives), a film of real index
// nFilm and thickness d, and a substrate of complex index n3 (a dielectric, or a conductor
// n + i k). The film's complex amplitudes are the Airy sum of the waves reflected back and
// forth inside it (Born and Wolf, "Principles of Optics", section 1.6.4, eqs. 55 and 56 with
// the film's phase thickness beta of eq. 38):
//   r = (r12 + r23 e^{2 i beta}) / (1 + r12 r23 e^{2 i beta})
//   t = t12 t23 e^{i beta} / (1 + r12 r23 e^{2 i beta}),   beta = 2 pi nFilm d cos_2 / lambda,
// per polarisation, with each interface's r and t in lamina's convention (fresnel_amplitudes.h:
// x = s on every ray, y = d x s for its own direction; the products above follow a ray through
// the film, so the convention carries over unchanged). cos_2 and cos_3 follow from Snell's law
// n1 sin_1 = nFilm sin_2 = n3 sin_3 with the principal roots: an evanescent film (cos_2
// imaginary) decays, as under total internal reflection.
//
// The reflectance as a Fourier series in the phase (Belcour and Barla 2017, "A Practical
// Extension to Microfacet Theory for the Modeling of Varying Iridescence", eqs. 7 and 8, for a
// film whose first interface is lossless): with R12 = |r12|^2, R23 = |r23|^2, T12 = 1 - R12,
//   R = C0 + 2 sum_{m >= 1} C_m cos(m (phi + psi)),  phi = 2 pi OPD / lambda, OPD = 2 nFilm d cos_2
//   C0 = R12 + T12^2 R23 / (1 - R12 R23),  C_m = (C0 - 1) (R12 R23)^{m/2},  psi = arg(-r12 r23),
// which is what lets RGB mode integrate R against a colour's sensitivity in closed form
// (bsdf/thin_film.h).
#pragma once

#include <complex>
#include <optional>

#include "lamina/core/fresnel_amplitudes.h"

namespace lamina {

/// The layers of a film stack: real indices of the incident medium and the film, the complex
/// index of the substrate, all absolute (or all relative to the same medium).
template <std::floating_point T>
struct FilmStack {
    T n1 = T(1);
    T nFilm = T(1.33);
    std::complex<T> n3{T(1.5), T(0)};
};

namespace detail {

/// cos(theta) in a medium of complex index n for light arriving in medium n1 at sin^2 =
/// sin2ThetaI: the principal root of 1 - (n1 / n)^2 sin^2, formed in real arithmetic for a
/// real index (a -0 imaginary part would take the growing wave's branch).
template <std::floating_point T>
std::complex<T> filmCosine(T n1, std::complex<T> n, T sin2ThetaI) {
    using C = std::complex<T>;
    const T s = sqr(n1) * sin2ThetaI;
    const C n2 = n * n;
    const C sin2 =
        n.imag() == T(0) ? C(s / sqr(n.real()), T(0)) : std::conj(n2) * (s / std::norm(n2));
    return principalSqrt(C(1) - sin2);
}

/// a / b as a conj(b) / |b|^2: libgcc's complex division (__divdc3, with its C99 infinity
/// handling) was a fifth of a film's cost; the denominators here are never 0 or huge.
template <std::floating_point T>
std::complex<T> quotient(std::complex<T> a, std::complex<T> b) {
    return a * std::conj(b) / std::norm(b);
}

/// One interface's amplitudes from medium a to medium b (complex indices and cosines), in
/// lamina's sign convention; an index-matched boundary at grazing incidence passes the light.
template <std::floating_point T>
void interfaceAmplitudes(std::complex<T> a, std::complex<T> cosA, std::complex<T> b,
                         std::complex<T> cosB, std::complex<T>& rs, std::complex<T>& rp,
                         std::complex<T>& ts, std::complex<T>& tp) {
    using C = std::complex<T>;
    const C sDen = a * cosA + b * cosB, pDen = b * cosA + a * cosB;
    if (std::norm(sDen) == T(0) || std::norm(pDen) == T(0)) {
        rs = rp = C(0);
        ts = tp = C(1);
        return;
    }
    rs = quotient(a * cosA - b * cosB, sDen);
    rp = quotient(b * cosA - a * cosB, pDen);
    ts = quotient(T(2) * a * cosA, sDen);
    tp = quotient(T(2) * a * cosA, pDen);
}

}  // namespace detail

/// The film's amplitudes for light arriving at `cosThetaI` (in [0, 1]) in medium n1, with the
/// film's thickness over the vacuum wavelength `thicknessOverLambda` (d / lambda, both in the
/// same unit). With thickness 0 they are the bare n1 | n3 interface's.
/// `transmittedPowerFactor` is Re(n3 cos_3) / (n1 cos_1) for a lossless substrate that the
/// light enters, else 0 (a conductor, or total reflection).
template <std::floating_point T>
FresnelAmplitudes<T> thinFilmAmplitudes(T cosThetaI, const FilmStack<T>& stack,
                                        T thicknessOverLambda) {
    using C = std::complex<T>;
    cosThetaI = clamp(cosThetaI, T(0), T(1));
    const T sin2ThetaI = T(1) - sqr(cosThetaI);
    const C n1(stack.n1), n2(stack.nFilm), n3 = stack.n3;
    const C cos1(cosThetaI);
    const C cos2 = detail::filmCosine(stack.n1, n2, sin2ThetaI);
    const C cos3 = detail::filmCosine(stack.n1, n3, sin2ThetaI);
    C rs12, rp12, ts12, tp12, rs23, rp23, ts23, tp23;
    detail::interfaceAmplitudes(n1, cos1, n2, cos2, rs12, rp12, ts12, tp12);
    detail::interfaceAmplitudes(n2, cos2, n3, cos3, rs23, rp23, ts23, tp23);
    // e^{i beta}: Im(cos_2) >= 0, so an evanescent film attenuates.
    const C beta = T(2) * kPi<T> * stack.nFilm * thicknessOverLambda * cos2;
    const C once = std::exp(C(0, 1) * beta), twice = once * once;
    FresnelAmplitudes<T> a;
    const auto combine = [&](C r12, C r23, C t12, C t23, C& r, C& t) {
        const C den = C(1) + r12 * r23 * twice;
        if (std::norm(den) == T(0)) {  // only at grazing incidence: the first interface's r
            r = r12;
            t = C(0);
            return;
        }
        r = detail::quotient(r12 + r23 * twice, den);
        t = detail::quotient(t12 * t23 * once, den);
    };
    combine(rs12, rs23, ts12, ts23, a.rs, a.ts);
    combine(rp12, rp23, tp12, tp23, a.rp, a.tp);
    const bool lossless = n3.imag() == T(0);
    const bool propagating = cos3.imag() == T(0) && cos3.real() > T(0);
    if (lossless && propagating && cosThetaI > T(0))
        a.transmittedPowerFactor = n3.real() * cos3.real() / (stack.n1 * cosThetaI);
    return a;
}

/// The Fourier series of one polarisation's film reflectance in the phase phi = 2 pi OPD /
/// lambda (Belcour and Barla 2017, eqs. 7 and 8; see the top of this file): R(phi) = c0 +
/// 2 (c0 - 1) sum_m ratio^m cos(m (phi + psi)).
template <std::floating_point T>
struct AirySeries {
    T c0 = T(0);
    T ratio = T(0);                    ///< sqrt(R12 R23)
    std::complex<T> turn{T(1), T(0)};  ///< exp(i psi), psi = arg(-r12 r23)
};

/// The series of both polarisations and the optical path difference per unit thickness,
/// 2 nFilm cos_2; nullopt where the film is evanescent (cos_2 imaginary: then no fringes).
template <std::floating_point T>
struct AiryFourier {
    AirySeries<T> s, p;
    T opdPerThickness = T(0);
};

template <std::floating_point T>
std::optional<AiryFourier<T>> airyFourier(T cosThetaI, const FilmStack<T>& stack) {
    using C = std::complex<T>;
    cosThetaI = clamp(cosThetaI, T(0), T(1));
    const T sin2ThetaI = T(1) - sqr(cosThetaI);
    const C n1(stack.n1), n2(stack.nFilm), n3 = stack.n3;
    const C cos2 = detail::filmCosine(stack.n1, n2, sin2ThetaI);
    if (cos2.imag() != T(0)) return std::nullopt;
    const C cos3 = detail::filmCosine(stack.n1, n3, sin2ThetaI);
    C rs12, rp12, ts12, tp12, rs23, rp23, ts23, tp23;
    detail::interfaceAmplitudes(n1, C(cosThetaI), n2, cos2, rs12, rp12, ts12, tp12);
    detail::interfaceAmplitudes(n2, cos2, n3, cos3, rs23, rp23, ts23, tp23);
    const auto series = [](C r12, C r23) {
        const T R12 = std::norm(r12), R23 = std::norm(r23), T12 = T(1) - R12;
        const T den = T(1) - R12 * R23;
        AirySeries<T> a;
        // R12 R23 = 1 only at grazing incidence (R12 = 1): everything is reflected.
        a.c0 = den > T(0) ? R12 + sqr(T12) * R23 / den : T(1);
        a.ratio = std::sqrt(R12 * R23);
        const C q = -r12 * r23;
        const T qAbs = std::abs(q);
        if (qAbs > T(0)) a.turn = q / qAbs;
        return a;
    };
    return AiryFourier<T>{series(rs12, rs23), series(rp12, rp23), T(2) * stack.nFilm * cos2.real()};
}

}  // namespace lamina
