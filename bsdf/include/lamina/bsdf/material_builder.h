// MaterialDesc -> BSDF of a variant. Lobes with zero weight are dropped here, so a render
// never evaluates them (a scene pays only for what it uses).
#pragma once

#include <memory>
#include <stdexcept>

#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse_transmission.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/material.h"
#include "lamina/bsdf/mix.h"
#include "lamina/bsdf/optical_sheet.h"
#include "lamina/bsdf/spectrum_context.h"
#include "lamina/bsdf/thin_dielectric.h"

namespace lamina {

/// The Rec.709 F0 and F82 of a conductor given per channel by (eta, k): the exact Fresnel
/// reflectance at normal incidence and at cos = 1/7 (Hoffman 2019's reduction, per channel).
inline std::pair<RgbInput, RgbInput> conductorF0F82(const RgbInput& eta, const RgbInput& k) {
    RgbInput f0, f82;
    for (int c = 0; c < 3; ++c) {
        f0[c] = fresnelConductor(1.0, eta[c], k[c]);
        f82[c] = fresnelConductor(kF82Cosine, eta[c], k[c]);
    }
    return {f0, f82};
}

template <SpectrumType S>
class MaterialBuilder {
  public:
    using Float = typename S::Float;
    using Distribution = MicrofacetDistribution<Float>;

    /// `walkSeed` seeds the random walks of `coated` materials (a render passes its own seed:
    /// docs/bsdf.md, "Random numbers").
    explicit MaterialBuilder(const SpectrumContext<S>& context, std::uint64_t walkSeed = 0)
        : ctx_(context), walkSeed_(walkSeed) {}

    std::unique_ptr<Bxdf<S>> build(const MaterialDesc& desc) const {
        return std::visit([&](const auto& m) { return buildModel(m); }, desc.model);
    }

  private:
    static Distribution distribution(const MicrofacetParams& m) {
        return Distribution(m.ndf, Float(m.alphaX), Float(m.alphaY));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const DiffuseMaterial& d) const {
        // A black diffuse surface (an emitter's back, say) has no lobe at all.
        if (d.reflectance.rgb.maxValue() <= 0.0 && !d.reflectance.spectrum)
            return std::make_unique<LayeredBxdf<S>>(typename LayeredBxdf<S>::Layers{});
        return std::make_unique<DiffuseBxdf<S>>(ctx_.reflectance(d.reflectance), d.model,
                                                Float(d.roughness));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const DielectricMaterial& d) const {
        const Float eta = d.spectrum ? ctx_.dielectricIor(*d.spectrum) : Float(d.ior);
        return std::make_unique<DielectricBxdf<S>>(eta, distribution(d.microfacet), d.microfacet.g2,
                                                   thinFilm(d.thinFilm));
    }

    // The film of a material in this variant: spectral variants evaluate it at the path's
    // wavelengths; RGB mode takes its polarisation shape at the channels' centre wavelengths.
    std::optional<ThinFilm<S>> thinFilm(const std::optional<ThinFilmParams>& p) const {
        if (!p) return std::nullopt;
        ThinFilm<S> film;
        film.thicknessNm = Float(p->thicknessNm);
        film.ior = Float(p->ior);
        for (int i = 0; i < S::kSize; ++i) {
            if constexpr (SpectrumContext<S>::kSpectral)
                film.wavelengthsNm[i] = ctx_.wavelength(i);
            else
                film.wavelengthsNm[i] = Float(FringeColors::rec709().meanWavelength(i));
        }
        return film;
    }

    // A filmed conductor's exact Fresnel model with its film. RGB mode takes n and k per
    // channel: the numbers given, or a spectrum's n, k at the channel's centre wavelength
    // (FringeColors::meanWavelength), since the film's closed form needs an index per channel
    // (Hoffman's F82 cannot carry a film).
    Fresnel<S> filmedConductorFresnel(const ConductorMaterial& c) const {
        const ConductorOptics& o = c.optics;
        Fresnel<S> f;
        if (o.form == ConductorOptics::Form::Spectral) {
            if constexpr (SpectrumContext<S>::kSpectral) {
                f = conductorFresnel(c);  // exact at the path's wavelengths
            } else {
                S eta, k;
                for (int i = 0; i < S::kSize; ++i) {
                    const double nm = FringeColors::rec709().meanWavelength(i);
                    const NkTable::Nk nk = o.table
                                               ? (*o.table)(nm)
                                               : NkTable::Nk{o.spectrum->n(nm), o.spectrum->k(nm)};
                    eta[i] = Float(nk.n);
                    k[i] = Float(nk.k);
                }
                f = Fresnel<S>::conductor(eta, k);
            }
        } else {
            f = Fresnel<S>::conductor(ctx_.unbounded(o.eta), ctx_.unbounded(o.k));
        }
        f.film = thinFilm(c.thinFilm);
        return f;
    }

    std::unique_ptr<Bxdf<S>> buildModel(const DiffuseTransmissionMaterial& d) const {
        const S r = ctx_.reflectance(d.reflectance), t = ctx_.reflectance(d.transmittance);
        if (r.maxValue() <= Float(0) && t.maxValue() <= Float(0))
            return std::make_unique<LayeredBxdf<S>>(typename LayeredBxdf<S>::Layers{});
        return std::make_unique<DiffuseTransmissionBxdf<S>>(r, t);
    }

    std::unique_ptr<Bxdf<S>> buildModel(const ThinDielectricMaterial& t) const {
        return std::make_unique<ThinDielectricBxdf<S>>(
            t.spectrum ? ctx_.indexPerChannel(*t.spectrum) : S(Float(t.ior)));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const PolariserMaterial& p) const {
        return std::make_unique<OpticalSheetBxdf<S>>(OpticalSheetBxdf<S>::Element::Polariser,
                                                     Vec3<Float>(p.axis), Float(p.transmittance),
                                                     Float(0));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const RetarderMaterial& r) const {
        return std::make_unique<OpticalSheetBxdf<S>>(
            OpticalSheetBxdf<S>::Element::Retarder, Vec3<Float>(r.axis), Float(1),
            Float(r.retardanceDegrees * kPi<double> / 180.0));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const PhongMaterial& p) const {
        typename LayeredBxdf<S>::Layers layers;
        const S rho = ctx_.reflectance(p.reflectance);
        layers.interface.emplace(PhongLobe<S>(rho, Float(p.shininess), Fresnel<S>::schlick(rho)));
        return std::make_unique<LayeredBxdf<S>>(std::move(layers));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const MixMaterial& m) const {
        return std::make_unique<MixBxdf<S>>(build(*m.a), build(*m.b), Float(m.weight));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const CoatedMaterial& c) const {
        typename CoatedBxdf<S>::Medium medium;
        medium.thickness = Float(c.thickness);
        medium.albedo = ctx_.reflectance(c.albedo);
        medium.g = Float(c.g);
        // A coated base gets a seed of its own: with an index-matched coat its walk would see
        // the same pairs as this one, and the same seed would replay this walk's numbers.
        const MaterialBuilder baseBuilder(ctx_, hashValues({walkSeed_, 0x62617365ull}));
        return std::make_unique<CoatedBxdf<S>>(
            CoatInterface<S>(Float(c.ior), distribution(c.microfacet), c.microfacet.g2),
            baseBuilder.build(*c.base), medium, c.maxDepth, c.samples, walkSeed_);
    }

    Fresnel<S> conductorFresnel(const ConductorMaterial& c) const {
        const ConductorOptics& o = c.optics;
        if (o.form == ConductorOptics::Form::Spectral) {
            // Spectral mode: the exact Fresnel equations at the path's wavelengths. RGB mode
            // (and the approximations in spectral mode): the reductions F0, F82 of the same
            // n, k (Hoffman 2019), so the two modes differ only by the approximation.
            if constexpr (SpectrumContext<S>::kSpectral) {
                if (c.fresnel == FresnelChoice::Auto || c.fresnel == FresnelChoice::Exact) {
                    S eta, k;
                    for (int i = 0; i < S::kSize; ++i) {
                        const double nm = double(ctx_.wavelength(i));
                        const NkTable::Nk nk =
                            o.table ? (*o.table)(nm)
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
            return conductorFresnel(reduced);
        }
        if (o.form == ConductorOptics::Form::F0F82) {
            const S f0 = ctx_.reflectance(o.f0);
            switch (c.fresnel) {
                case FresnelChoice::Schlick:
                    return Fresnel<S>::schlick(f0);
                case FresnelChoice::SchlickShadowed:
                    return Fresnel<S>::schlickShadowed(f0, shadowedF90(o.f0));
                case FresnelChoice::SchlickSphericalGaussian:
                    return Fresnel<S>::schlickSphericalGaussian(f0);
                default:  // Auto, F82 (Exact is rejected by the parser)
                    return o.f82 ? Fresnel<S>::hoffmanF82(f0, ctx_.reflectance(*o.f82))
                                 : Fresnel<S>::schlick(f0);
            }
        }
        // Exact conductor Fresnel: per channel in RGB mode; in spectral mode with eta and k
        // upsampled as unbounded spectra (pbrt-v4's convention, so that the same numbers are
        // the same metal there; grey values are constant spectra). RGB mode's default is
        // Hoffman's F82 through the exact reflectance per channel.
        if (c.fresnel == FresnelChoice::Exact ||
            (c.fresnel == FresnelChoice::Auto && SpectrumContext<S>::kSpectral))
            return Fresnel<S>::conductor(ctx_.unbounded(o.eta), ctx_.unbounded(o.k));
        // The approximations take the reflectances F0 and F82 of eta and k per channel (never
        // eta and k upsampled as if they were albedos: Mitsuba 3 issue 208).
        const auto [f0rgb, f82rgb] = conductorF0F82(o.eta, o.k);
        const S f0 = ctx_.reflectance(f0rgb);
        switch (c.fresnel) {
            case FresnelChoice::Schlick:
                return Fresnel<S>::schlick(f0);
            case FresnelChoice::SchlickShadowed:
                return Fresnel<S>::schlickShadowed(f0, shadowedF90(f0rgb));
            case FresnelChoice::SchlickSphericalGaussian:
                return Fresnel<S>::schlickSphericalGaussian(f0);
            default:
                return Fresnel<S>::hoffmanF82(f0, ctx_.reflectance(f82rgb));
        }
    }

    ConductorBxdf<S> conductorBxdf(const ConductorMaterial& c) const {
        const Fresnel<S> fresnel = c.thinFilm ? filmedConductorFresnel(c) : conductorFresnel(c);
        std::optional<MultiscatterLobe<S>> ms;
        if (c.microfacet.multiscatter && c.microfacet.energyF1)
            ms.emplace(c.microfacet.energyF1, fresnel);
        return ConductorBxdf<S>(MicrofacetReflectionLobe<S>(distribution(c.microfacet), fresnel,
                                                            c.microfacet.sampling, c.microfacet.g2),
                                std::move(ms));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const ConductorMaterial& c) const {
        return std::make_unique<ConductorBxdf<S>>(conductorBxdf(c));
    }

    // The article's F90 = min(1, luminance(F0) / 0.04), from the Rec.709 F0 in both modes.
    static S shadowedF90(const RgbInput& f0) {
        return S(Float(std::min(1.0, luminance(f0) / 0.04)));
    }

    std::unique_ptr<Bxdf<S>> buildModel(const StandardMaterial& s) const {
        // The article, section 4.3.1: F0 = lerp(0.04, base_color, metalness) (with `specular` in
        // place of 0.04), diffuse reflectance = base_color (1 - metalness).
        const RgbInput f0rgb = s.specularColor ? *s.specularColor
                                               : RgbInput(s.specular) * (1.0 - s.metalness) +
                                                     s.baseColor.rgb * s.metalness;
        const RgbInput diffuseRgb =
            s.specularColor ? s.baseColor.rgb : s.baseColor.rgb * (1.0 - s.metalness);
        // A spectral base colour mixes in the spectral domain; an RGB one is mixed in RGB
        // first (so RGB inputs are upsampled once, as they always were).
        const bool spectralBase = s.baseColor.spectrum != nullptr;
        const auto f0Spectrum = [&]() -> S {
            if (!spectralBase || s.specularColor) return ctx_.reflectance(f0rgb);
            return S(Float(s.specular * (1.0 - s.metalness))) +
                   ctx_.reflectance(s.baseColor) * Float(s.metalness);
        };
        const auto diffuseSpectrum = [&]() -> S {
            if (!spectralBase) return ctx_.reflectance(diffuseRgb);
            return ctx_.reflectance(s.baseColor) * Float(s.specularColor ? 1.0 : 1.0 - s.metalness);
        };

        typename LayeredBxdf<S>::Layers layers;
        layers.coupling = s.coupling;
        const Distribution dist = distribution(s.microfacet);
        if (s.specularLobe) {
            const S f0 = f0Spectrum();
            Fresnel<S> fresnel;
            switch (s.fresnel) {
                case FresnelChoice::Schlick:
                    fresnel = Fresnel<S>::schlick(f0);
                    break;
                case FresnelChoice::SchlickSphericalGaussian:
                    fresnel = Fresnel<S>::schlickSphericalGaussian(f0);
                    break;
                case FresnelChoice::F82:
                    if (s.f82)
                        fresnel = Fresnel<S>::hoffmanF82(f0, ctx_.reflectance(*s.f82));
                    else
                        fresnel = Fresnel<S>::hoffmanF82Tint(
                            f0, ctx_.unbounded(s.f82Tint.value_or(RgbInput(1.0))));
                    break;
                case FresnelChoice::Exact:
                    fresnel = Fresnel<S>::dielectric(S(Float(s.ior)));
                    break;
                default:
                    fresnel = Fresnel<S>::schlickShadowed(f0, shadowedF90(f0rgb));
                    break;
            }
            if (s.phong) {
                // The article's Phong specular: reflectance F0, exponent from alpha.
                const Float alpha = Float(0.5 * (s.microfacet.alphaX + s.microfacet.alphaY));
                layers.interface.emplace(
                    PhongLobe<S>(f0, PhongLobe<S>::shininessFromAlpha(alpha), fresnel));
            } else {
                layers.interface.emplace(dist, fresnel, s.microfacet.sampling, s.microfacet.g2);
            }
            if (s.microfacet.multiscatter && s.microfacet.energyF1 && !s.phong)
                layers.interfaceMultiscatter.emplace(s.microfacet.energyF1, fresnel);
        }
        layers.interfaceAlbedo = s.interfaceAlbedo;
        if (s.diffuse && s.transmission < 1.0 && (diffuseRgb.maxValue() > 0.0 || spectralBase))
            layers.diffuse.emplace(
                diffuseSpectrum(), *s.diffuse,
                Float(s.diffuseRoughness.value_or(s.microfacet.perceptualRoughness())));
        if (s.conductorBase)  // seen through the interface of index ior (none: index 1)
            layers.conductorBase.emplace(conductorBxdf(*s.conductorBase),
                                         Float(s.specularLobe ? s.ior : 1.0));
        if (s.transmission > 0.0) {
            layers.transmission.emplace(Float(s.ior), dist, s.microfacet.g2);
            layers.transmissionWeight = Float(s.transmission);
        }
        return std::make_unique<LayeredBxdf<S>>(std::move(layers));
    }

    const SpectrumContext<S>& ctx_;
    std::uint64_t walkSeed_;
};

/// The single-scattering albedo table of a microfacet lobe with F = 1 (what Kulla-Conty
/// compensation needs), computed from the lobe itself.
inline std::shared_ptr<const AlbedoTable> microfacetEnergyTable(const MicrofacetParams& m) {
    using S = Rgb<double>;
    const MicrofacetReflectionLobe<S> lobe(
        MicrofacetDistribution<double>(m.ndf, std::max(m.alphaX, kSmoothAlpha),
                                       std::max(m.alphaY, kSmoothAlpha)),
        Fresnel<S>::schlick(S(1.0)), MicrofacetSampling::VisibleNormals, m.g2);
    return std::make_shared<const AlbedoTable>(
        AlbedoTable::compute([&](const Vec3<double>& wo, double u1, double u2, double) {
            const auto r = lobe.sample(wo, {u1, u2});
            return r ? r->weight.average() : 0.0;
        }));
}

/// Fills in the tables a material's energy options need (called once, when it is parsed).
void prepareEnergyTables(StandardMaterial& s);
void prepareEnergyTables(ConductorMaterial& c);

/// Builds the BSDF of `desc` in the variant of `context`; `walkSeed` as in MaterialBuilder.
template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildBxdf(const MaterialDesc& desc, const SpectrumContext<S>& context,
                                   std::uint64_t walkSeed = 0) {
    return MaterialBuilder<S>(context, walkSeed).build(desc);
}

// The BSDF templates are compiled once, in bsdf_instantiations.cpp, for the four variants.
// Without these declarations every file that builds a material (every renderer file that
// includes render_mode.h, every command, every test) compiled the whole stack again for each
// variant it touched: about a third of a renderer file's compile time, and of the CI's.
// Callers reach the models through Bxdf's virtual functions, so nothing they inline is lost.
#define LAMINA_EXTERN_BSDF_VARIANTS(Class)               \
    extern template class Class<Rgb<float>>;             \
    extern template class Class<Rgb<double>>;            \
    extern template class Class<SampledSpectrum<float>>; \
    extern template class Class<SampledSpectrum<double>>;
LAMINA_EXTERN_BSDF_VARIANTS(DiffuseBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(ConductorBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(DielectricBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(DiffuseTransmissionBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(ThinDielectricBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(OpticalSheetBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(LayeredBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(MicrofacetReflectionLobe)
LAMINA_EXTERN_BSDF_VARIANTS(MixBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(CoatedBxdf)
LAMINA_EXTERN_BSDF_VARIANTS(MaterialBuilder)
#undef LAMINA_EXTERN_BSDF_VARIANTS
extern template class MicrofacetDistribution<float>;
extern template class MicrofacetDistribution<double>;

}  // namespace lamina
