// A conductor: specular reflection only, smooth (a delta lobe) when alpha is below
// kSmoothAlpha and rough (microfacet) otherwise, with any Fresnel model, optionally with
// Kulla-Conty multiple-scattering compensation (multiscatter.h). Two-sided.
//
// With compensation, sampling picks the microfacet lobe or the cosine-sampled compensation
// lobe in proportion to estimates of their albedos at wo; weight = eval / pdf of the mixture.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/microfacet_reflection.h"
#include "lamina/bsdf/multiscatter.h"
#include "lamina/bsdf/polarised_fresnel.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/nk_table.h"

namespace lamina {

template <SpectrumType S>
class ConductorBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    explicit ConductorBxdf(const MicrofacetReflectionLobe<S>& lobe,
                           std::optional<MultiscatterLobe<S>> multiscatter = std::nullopt)
        : lobe_(lobe), ms_(isSmooth() ? std::nullopt : std::move(multiscatter)) {}

    bool isSmooth() const { return lobe_.distribution().effectivelySmooth(); }
    const MicrofacetReflectionLobe<S>& lobe() const { return lobe_; }

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (isSmooth()) return S(Float(0));
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        S f = lobe_.eval(wo * s, wi * s);
        if (ms_) f += ms_->eval(wo * s, wi * s);
        return f;
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (isSmooth()) return Float(0);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        const V3 o = wo * s, i = wi * s;
        if (!ms_) return lobe_.pdf(o, i);
        const Float p = multiscatterProbability(o.z);
        return (Float(1) - p) * lobe_.pdf(o, i) + p * cosineHemispherePdf(i);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        if (isSmooth()) {
            const V3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample<S>{wi, lobe_.fresnel().evaluate(std::abs(wo.z)), Float(1),
                                 kLobeSpecularReflection, Float(1)};
        }
        if (!ms_) {
            const auto r = lobe_.sample(wo * s, u);
            if (!r) return std::nullopt;
            return BsdfSample<S>{r->wi * s, r->weight, r->pdf, kLobeGlossyReflection, Float(1)};
        }
        V3 wi;
        if (uc < multiscatterProbability(std::abs(wo.z))) {
            wi = squareToCosineHemisphere(u) * s;
        } else {
            const auto r = lobe_.sample(wo * s, u);
            if (!r) return std::nullopt;
            wi = r->wi * s;
        }
        const Float p = pdf(wo, wi);
        if (!(p > Float(0)) || !std::isfinite(p)) return std::nullopt;
        const S weight = eval(wo, wi, mode) / p;
        if (!weight.isFinite()) return std::nullopt;
        return BsdfSample<S>{wi, weight, p, kLobeGlossyReflection, Float(1)};
    }

    /// The microfacet lobe polarises as its Fresnel model does on each microfacet; the
    /// multiple-scattering compensation lobe is an ideal depolariser.
    MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode) const override {
        if (isSmooth()) return MuellerMatrix<S>();
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        MuellerMatrix<S> m = reflectionMueller(lobe_.eval(wo * s, wi * s), lobe_.fresnel(), wo, wi);
        if (ms_) m += depolarising(ms_->eval(wo * s, wi * s));
        return m;
    }

    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        if (!s.isSpecular()) return evalMueller(wo, s.wi, mode) / s.pdf;
        return reflectionMueller(s.weight, lobe_.fresnel(), wo, s.wi);
    }

    std::uint32_t flags() const override {
        return isSmooth() ? kLobeSpecularReflection : kLobeGlossyReflection;
    }

  private:
    // Share of the compensation lobe: its albedo against the single-scattering lobe's
    // (estimated by E(mu) times the mean Fresnel), with at least 5% each.
    Float multiscatterProbability(Float muO) const {
        const Float ms = ms_->albedo(muO).average();
        const Float ss = Float(ms_->table()(muO)) * lobe_.fresnel().evaluate(muO).average();
        const Float total = ms + ss;
        return total > Float(0) ? clamp(ms / total, Float(0.05), Float(0.95)) : Float(0.5);
    }

    MicrofacetReflectionLobe<S> lobe_;
    std::optional<MultiscatterLobe<S>> ms_;
};

LAMINA_EXTERN_BSDF_VARIANTS(ConductorBxdf)

/// A conductor's optics: exactly one form.
struct ConductorOptics {
    /// EtaK: numbers per channel; F0F82: reflectances; Spectral: n, k as functions of
    /// wavelength (a named metal or an n/k file), with its RGB-mode reductions precomputed.
    enum class Form { EtaK, F0F82, Spectral };
    Form form = Form::EtaK;
    RgbInput eta{0.2};            ///< EtaK: real part of the relative index (per channel)
    RgbInput k{3.9};              ///< EtaK: imaginary part
    RgbInput f0{0.9};             ///< F0F82: normal-incidence reflectance
    std::optional<RgbInput> f82;  ///< F0F82: reflectance at cos = 1/7 (absent: plain Schlick)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< Spectral (f0 and f82 hold its reductions)
    /// Spectral: `spectrum` tabulated at 1 nm, what spectral mode evaluates at every path's
    /// wavelengths. Without it (a description built by hand) the spectrum is evaluated
    /// directly.
    std::shared_ptr<const NkTable> table;
    /// Spectral optics from n, k: the table and the RGB-mode reductions F0, F82 with it.
    static ConductorOptics fromSpectrum(std::shared_ptr<const IorSpectrum> spectrum);
};

/// `conductor` (conductor_reader.cpp). Fresnel: Auto is exact for eta/k optics and Hoffman's F82
/// for f0/f82.
struct ConductorMaterial {
    ConductorOptics optics;
    MicrofacetParams microfacet;
    FresnelChoice fresnel = FresnelChoice::Auto;
    std::optional<ThinFilmParams> thinFilm;  ///< needs n, k optics and the exact Fresnel
};

// How a conductor description becomes a BSDF: its Fresnel model in the variant (exact from n, k
// or an approximation from F0, F82), with a thin film when it has one.

template <SpectrumType S>
Fresnel<S> conductorFresnel(const ConductorMaterial& c, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    const ConductorOptics& o = c.optics;
    if (o.form == ConductorOptics::Form::Spectral) {
        // Spectral mode: the exact Fresnel equations at the path's wavelengths. RGB mode
        // (and the approximations in spectral mode): the reductions F0, F82 of the same
        // n, k (Hoffman 2019), so the two modes differ only by the approximation.
        if constexpr (SpectrumContext<S>::kSpectral) {
            if (c.fresnel == FresnelChoice::Auto || c.fresnel == FresnelChoice::Exact) {
                S eta, k;
                for (int i = 0; i < S::kSize; ++i) {
                    const double nm = double(b.context().wavelength(i));
                    const NkTable::Nk nk = o.table
                                               ? (*o.table)(nm)
                                               : NkTable::Nk{o.spectrum->n(nm), o.spectrum->k(nm)};
                    eta[i] = Float(nk.n);
                    k[i] = Float(nk.k);
                }
                return Fresnel<S>::conductor(eta, k);
            }
        }
        ConductorMaterial reduced = c;
        reduced.optics.form = ConductorOptics::Form::F0F82;
        if (reduced.fresnel == FresnelChoice::Exact) reduced.fresnel = FresnelChoice::F82;
        return conductorFresnel(reduced, b);
    }
    if (o.form == ConductorOptics::Form::F0F82) {
        const S f0 = b.context().reflectance(o.f0);
        switch (c.fresnel) {
            case FresnelChoice::Schlick:
                return Fresnel<S>::schlick(f0);
            case FresnelChoice::SchlickShadowed:
                return Fresnel<S>::schlickShadowed(f0, MaterialBuilder<S>::shadowedF90(o.f0));
            case FresnelChoice::SchlickSphericalGaussian:
                return Fresnel<S>::schlickSphericalGaussian(f0);
            default:  // Auto, F82 (Exact is rejected by the parser)
                return o.f82 ? Fresnel<S>::hoffmanF82(f0, b.context().reflectance(*o.f82))
                             : Fresnel<S>::schlick(f0);
        }
    }
    // Exact conductor Fresnel: per channel in RGB mode; in spectral mode with eta and k
    // upsampled as unbounded spectra (pbrt-v4's convention, so that the same numbers are
    // the same metal there; grey values are constant spectra). RGB mode's default is
    // Hoffman's F82 through the exact reflectance per channel.
    if (c.fresnel == FresnelChoice::Exact ||
        (c.fresnel == FresnelChoice::Auto && SpectrumContext<S>::kSpectral))
        return Fresnel<S>::conductor(b.context().unbounded(o.eta), b.context().unbounded(o.k));
    // The approximations take the reflectances F0 and F82 of eta and k per channel (never
    // eta and k upsampled as if they were albedos: Mitsuba 3 issue 208).
    const auto [f0rgb, f82rgb] = conductorF0F82(o.eta, o.k);
    const S f0 = b.context().reflectance(f0rgb);
    switch (c.fresnel) {
        case FresnelChoice::Schlick:
            return Fresnel<S>::schlick(f0);
        case FresnelChoice::SchlickShadowed:
            return Fresnel<S>::schlickShadowed(f0, MaterialBuilder<S>::shadowedF90(f0rgb));
        case FresnelChoice::SchlickSphericalGaussian:
            return Fresnel<S>::schlickSphericalGaussian(f0);
        default:
            return Fresnel<S>::hoffmanF82(f0, b.context().reflectance(f82rgb));
    }
}

// A filmed conductor's exact Fresnel model with its film. RGB mode takes n and k per
// channel: the numbers given, or a spectrum's n, k at the channel's centre wavelength
// (FringeColors::meanWavelength), since the film's closed form needs an index per channel
// (Hoffman's F82 cannot carry a film).
template <SpectrumType S>
Fresnel<S> filmedConductorFresnel(const ConductorMaterial& c, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    const ConductorOptics& o = c.optics;
    Fresnel<S> f;
    if (o.form == ConductorOptics::Form::Spectral) {
        if constexpr (SpectrumContext<S>::kSpectral) {
            f = conductorFresnel(c, b);  // exact at the path's wavelengths
        } else {
            S eta, k;
            for (int i = 0; i < S::kSize; ++i) {
                const double nm = FringeColors::rec709().meanWavelength(i);
                const NkTable::Nk nk =
                    o.table ? (*o.table)(nm) : NkTable::Nk{o.spectrum->n(nm), o.spectrum->k(nm)};
                eta[i] = Float(nk.n);
                k[i] = Float(nk.k);
            }
            f = Fresnel<S>::conductor(eta, k);
        }
    } else {
        f = Fresnel<S>::conductor(b.context().unbounded(o.eta), b.context().unbounded(o.k));
    }
    f.film = b.thinFilm(c.thinFilm);
    return f;
}

template <SpectrumType S>
ConductorBxdf<S> buildConductorBxdf(const ConductorMaterial& c, const MaterialBuilder<S>& b) {
    const Fresnel<S> fresnel = c.thinFilm ? filmedConductorFresnel(c, b) : conductorFresnel(c, b);
    std::optional<MultiscatterLobe<S>> ms;
    if (c.microfacet.multiscatter && c.microfacet.energyF1)
        ms.emplace(c.microfacet.energyF1, fresnel);
    return ConductorBxdf<S>(
        MicrofacetReflectionLobe<S>(MaterialBuilder<S>::distribution(c.microfacet), fresnel,
                                    c.microfacet.sampling, c.microfacet.g2),
        std::move(ms));
}

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const ConductorMaterial& c, const MaterialBuilder<S>& b) {
    return std::make_unique<ConductorBxdf<S>>(buildConductorBxdf(c, b));
}

LAMINA_MATERIAL_MODEL(ConductorMaterial)

}  // namespace lamina
