// The Mueller matrices of the BSDFs' Fresnel events, for the polarised mode
// (docs/polarisation.md). A lobe's Mueller matrix is its unpolarised value times the *shape*
// of its Fresnel event: the Fresnel Mueller matrix of each wavelength divided by its own
// [0][0], written in the event's s/p frames and turned into the canonical frames
// (stokesAxis) of the lobe's local directions. So the [0][0] element of every polarised
// evaluation is exactly the unpolarised value the other modes compute, and a BSDF only has to
// say where its Fresnel event is (the microfacet normal) and what index it sees.
//
// Indices: the exact dielectric and conductor models have theirs (eta, and k for conductors).
// The approximate models (Schlick and its variants, F82) have only reflectances; their
// polarisation is that of a dielectric with the same normal-incidence reflectance,
// eta = (1 + sqrt(F0)) / (1 - sqrt(F0)), which has the right Brewster-like dip in Rp but no
// phase (no retardance): docs/polarisation.md says so.
#pragma once

#include <complex>

#include "lamina/bsdf/fresnel.h"
#include "lamina/core/mueller_matrix.h"

namespace lamina {

/// The complex relative index (transmitted side over incident side) that `f` describes at the
/// cosine `cosTheta` to the microfacet normal, channel `i`, and the cosine on the incident side.
template <SpectrumType S>
std::pair<std::complex<typename S::Float>, typename S::Float> fresnelIndex(
    const Fresnel<S>& f, typename S::Float cosTheta, int i) {
    using F = typename S::Float;
    switch (f.kind) {
        case FresnelKind::ExactConductor:
            return {{f.eta[i], f.k[i]}, std::abs(cosTheta)};
        case FresnelKind::ExactDielectric:
            if (cosTheta < F(0)) return {F(1) / f.eta[i], -cosTheta};
            return {f.eta[i], cosTheta};
        default: {
            const F root = std::sqrt(clamp(f.f0[i], F(0), F(0.9999)));
            return {(F(1) + root) / (F(1) - root), std::abs(cosTheta)};
        }
    }
}

/// The complex amplitudes of `f` at the cosine `cosTheta` to the microfacet normal, channel
/// `i`: its film's, or the bare interface's.
template <SpectrumType S>
FresnelAmplitudes<typename S::Float> fresnelAmplitudesOf(const Fresnel<S>& f,
                                                         typename S::Float cosTheta, int i) {
    if (f.film) return f.film->amplitudes(i, f.filmSide(cosTheta, i));
    const auto [eta, cosI] = fresnelIndex(f, cosTheta, i);
    return fresnelAmplitudes(cosI, eta);
}

/// The Fresnel reflection (or transmission) Mueller matrix of each channel divided by its own
/// [0][0], in the event's s/p frames. A channel with nothing reflected (or transmitted) gets
/// the depolariser of [0][0] = 1: its value is 0 anyway.
template <SpectrumType S, typename AmplitudesOf>
MuellerMatrix<S> fresnelShape(bool transmission, AmplitudesOf&& amplitudesOf) {
    using F = typename S::Float;
    MuellerMatrix<S> shape;
    for (int i = 0; i < S::kSize; ++i) {
        const FresnelAmplitudes<F> a = amplitudesOf(i);
        const MuellerMatrix<F> m =
            transmission ? fresnelTransmissionMueller(a) : fresnelReflectionMueller(a);
        const F norm = m(0, 0);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                shape(r, c)[i] = norm > F(0) ? m(r, c) / norm : F(r == 0 && c == 0);
    }
    return shape;
}

/// A matrix written in the s/p frames of an event (x = s for the light arriving along dIn and
/// leaving along dOut, both propagation directions) turned into the canonical frames of dIn
/// and dOut. `m` is the microfacet (or surface) normal; at normal incidence, where every plane
/// contains dIn and m, dIn's canonical axis serves as s.
template <SpectrumType S>
MuellerMatrix<S> inCanonicalFrames(MuellerMatrix<S> shape, const Vec3<typename S::Float>& dIn,
                                   const Vec3<typename S::Float>& dOut,
                                   const Vec3<typename S::Float>& m) {
    using F = typename S::Float;
    const Vec3<F> inAxis = stokesAxis(dIn);
    const Vec3<F> s = planeOfIncidenceNormal(dIn, m, inAxis);
    turnInputFrame(shape, doubledFrameTurn(StokesFrame<F>{dIn, inAxis}, s));
    turnOutputFrame(shape, doubledFrameTurn(StokesFrame<F>{dOut, s}, stokesAxis(dOut)));
    return shape;
}

/// The Mueller matrix of a reflection lobe of value `value` (its unpolarised f |cos|) for
/// radiance leaving along wo and arriving from wi (local directions pointing away from the
/// surface, on the same side), its Fresnel model `f` evaluated on the half vector.
template <SpectrumType S>
MuellerMatrix<S> reflectionMueller(const S& value, const Fresnel<S>& f,
                                   const Vec3<typename S::Float>& wo,
                                   const Vec3<typename S::Float>& wi) {
    using F = typename S::Float;
    Vec3<F> m = safeNormalize(wo + wi);
    if (m == Vec3<F>(F(0))) return depolarising(value);
    if (m.z < F(0)) m = -m;  // as the lobes orient it: a negative cosine is "from inside"
    const F cosTheta = glm::dot(wo, m);
    MuellerMatrix<S> shape =
        fresnelShape<S>(false, [&](int i) { return fresnelAmplitudesOf(f, cosTheta, i); });
    return inCanonicalFrames(shape, -wi, wo, m) * value;
}

/// reflectionMueller for an interface that is the same seen from either side: the layered
/// stack's, which evaluates a pair below the surface as its mirror image above. Its Fresnel
/// model is the one light meets from the side of wo and wi, at |wo.m|, whichever side that is
/// (the dielectric's own reflectionMueller sees the inside's index from below).
template <SpectrumType S>
MuellerMatrix<S> twoSidedReflectionMueller(const S& value, const Fresnel<S>& f,
                                           const Vec3<typename S::Float>& wo,
                                           const Vec3<typename S::Float>& wi) {
    using F = typename S::Float;
    const Vec3<F> m = safeNormalize(wo + wi);
    if (m == Vec3<F>(F(0))) return depolarising(value);
    // m lies on the side of wo and wi; the plane of incidence, not m's sign, sets the frames.
    const F cosTheta = std::abs(glm::dot(wo, m));
    MuellerMatrix<S> shape =
        fresnelShape<S>(false, [&](int i) { return fresnelAmplitudesOf(f, cosTheta, i); });
    return inCanonicalFrames(shape, -wi, wo, m) * value;
}

/// The Mueller matrix of a transmission lobe of value `value`: radiance leaving along wo,
/// arriving from wi on the other side through the microfacet normal m (either orientation),
/// `etaLight` the relative index along the light's travel (wi's side to wo's). With a `film`
/// on the outside (z > 0) of the boundary, the film's transmission amplitudes.
template <SpectrumType S>
MuellerMatrix<S> transmissionMueller(const S& value, typename S::Float etaLight,
                                     const Vec3<typename S::Float>& wo,
                                     const Vec3<typename S::Float>& wi,
                                     const Vec3<typename S::Float>& m,
                                     const ThinFilm<S>* film = nullptr) {
    using F = typename S::Float;
    const F cosI = std::abs(glm::dot(wi, m));
    MuellerMatrix<S> shape = fresnelShape<S>(true, [&](int i) {
        if (film) {
            // etaLight > 1 enters the boundary from outside (eta = etaLight); from inside the
            // boundary's eta is 1 / etaLight.
            const bool fromOutside = wi.z > F(0);
            const F eta = fromOutside ? etaLight : F(1) / etaLight;
            return film->amplitudes(i,
                                    ThinFilm<S>::dielectricSide(fromOutside ? cosI : -cosI, eta));
        }
        return fresnelAmplitudes(cosI, std::complex<F>(etaLight));
    });
    return inCanonicalFrames(shape, -wi, wo, m) * value;
}

}  // namespace lamina
