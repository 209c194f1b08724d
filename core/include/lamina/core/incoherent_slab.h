// The Mueller matrices of a slab between two identical, parallel, smooth boundaries that is
// thick against the coherence length (a window pane: no interference, unlike thin_film.h).
// Light bounces between the boundaries and leaves by the top or the bottom; the bounces add as
// intensities, each polarisation on its own and the s-p correlation (the [2][2], [2][3]
// elements) by the same geometric series. Pure math for the polarised `thin_dielectric`.
//
// All events share the plane of incidence, so each order of the series is one field map
// E_s -> a E_s, E_p -> b E_p in the s/p frames (amplitudeMueller): with t, r the amplitudes
// entering the slab, t', r' those met from inside (Born and Wolf, "Principles of Optics",
// section 1.6.4, the plane-parallel plate, summed incoherently instead of as fields), and
// q = r'^2 a round trip inside,
//   reflection:   a_0 = r,  a_n = t t' r' q^(n-1)  (n >= 1),
//   transmission: a_n = t t' q^n                   (n >= 0),
// so sum |a_n|^2 and sum a_n conj(b_n) are geometric series in |q_s|^2 and q_s conj(q_p).
// The unpolarised slab of the other modes (thin_dielectric.h) sums the series with the
// reflectance averaged over s and p first; this keeps s and p apart, as two unpolarised
// boundaries cannot.
#pragma once

#include "lamina/core/fresnel_amplitudes.h"
#include "lamina/core/mueller_matrix.h"

namespace lamina {

template <std::floating_point T>
struct SlabMueller {
    MuellerMatrix<T> reflection;    ///< in the s/p frames of the incident and reflected rays
    MuellerMatrix<T> transmission;  ///< in the s/p frames of the incident and transmitted rays
};

/// The slab of relative index `eta` (slab over surroundings) for light arriving at the cosine
/// `cosThetaI` in [0, 1]. Lossless: per polarisation, reflection and transmission sum to one.
template <std::floating_point T>
SlabMueller<T> incoherentSlabMueller(T cosThetaI, T eta) {
    using C = std::complex<T>;
    const FresnelAmplitudes<T> enter = fresnelAmplitudes(cosThetaI, C(eta));
    SlabMueller<T> slab;
    slab.reflection = amplitudeMueller(enter.rs, enter.rp);
    slab.transmission = MuellerMatrix<T>::diagonal(T(0), T(0), T(0), T(0));
    // Total internal reflection at the first boundary (eta < 1): nothing enters.
    if (!(enter.transmittedPowerFactor > T(0))) return slab;
    const T cosInside = safeSqrt(T(1) - (T(1) - sqr(clamp(cosThetaI, T(0), T(1)))) / sqr(eta));
    const FresnelAmplitudes<T> leave = fresnelAmplitudes(cosInside, C(T(1) / eta));
    // In and out once, as power: the two transmitted-power factors multiply to 1 analytically.
    const T power = enter.transmittedPowerFactor * leave.transmittedPowerFactor;
    const C passS = enter.ts * leave.ts, passP = enter.tp * leave.tp;
    const C roundS = leave.rs * leave.rs, roundP = leave.rp * leave.rp;
    const T seriesS = T(1) - std::norm(roundS), seriesP = T(1) - std::norm(roundP);
    const C seriesSP = C(T(1)) - roundS * std::conj(roundP);
    // A boundary that reflects everything from inside (grazing light) lets nothing through.
    if (!(seriesS > T(0)) || !(seriesP > T(0)) || !(std::norm(seriesSP) > T(0))) return slab;
    const T throughS = std::norm(passS) * power / seriesS;
    const T throughP = std::norm(passP) * power / seriesP;
    const C throughSP = passS * std::conj(passP) * power / seriesSP;
    slab.transmission = incoherentSumMueller(throughS, throughP, throughSP);
    slab.reflection +=
        incoherentSumMueller(throughS * std::norm(leave.rs), throughP * std::norm(leave.rp),
                             throughSP * leave.rs * std::conj(leave.rp));
    return slab;
}

}  // namespace lamina
