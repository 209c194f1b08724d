// MaterialDesc -> BSDF of a variant. Each material type builds its own BSDF (`buildModel`, in
// its BSDF header); the builder carries what they share: the variant's SpectrumContext, the
// seed of random walks, and the conversions several types use. Lobes with zero weight are
// dropped by the types' builders, so a render never evaluates them (a scene pays only for what
// it uses).
#pragma once

#include <memory>

#include "lamina/bsdf/material.h"
#include "lamina/bsdf/microfacet_reflection.h"
#include "lamina/bsdf/spectrum_context.h"
#include "lamina/bsdf/thin_film.h"

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
        return desc.model.build(*this);
    }

    const SpectrumContext<S>& context() const { return ctx_; }
    std::uint64_t walkSeed() const { return walkSeed_; }

    static Distribution distribution(const MicrofacetParams& m) {
        return Distribution(m.ndf, Float(m.alphaX), Float(m.alphaY));
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

    // The article's F90 = min(1, luminance(F0) / 0.04), from the Rec.709 F0 in both modes.
    static S shadowedF90(const RgbInput& f0) {
        return S(Float(std::min(1.0, luminance(f0) / 0.04)));
    }

  private:
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

/// Builds the BSDF of `desc` in the variant of `context`; `walkSeed` as in MaterialBuilder.
template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildBxdf(const MaterialDesc& desc, const SpectrumContext<S>& context,
                                   std::uint64_t walkSeed = 0) {
    return MaterialBuilder<S>(context, walkSeed).build(desc);
}

// The BSDF templates and every material type's buildModel are compiled once, in one optimised
// file the build writes from these marks (cmake/GenerateBsdfInstantiations.cmake scans the
// headers of bsdf/include for them). Without the extern declarations every file that builds a
// material (every renderer file that includes render_mode.h, every command, every test)
// compiled the whole stack again for each variant it touched: about a third of a renderer
// file's compile time, and of the CI's. Callers reach the models through Bxdf's virtual
// functions, so nothing they inline is lost.

/// In a BSDF header, after `buildModel(const Model&, const MaterialBuilder<S>&)`: Model is a
/// material description, built in the four variants.
#define LAMINA_MATERIAL_MODEL(Model)                                           \
    extern template std::unique_ptr<Bxdf<Rgb<float>>> buildModel(              \
        const Model&, const MaterialBuilder<Rgb<float>>&);                     \
    extern template std::unique_ptr<Bxdf<Rgb<double>>> buildModel(             \
        const Model&, const MaterialBuilder<Rgb<double>>&);                    \
    extern template std::unique_ptr<Bxdf<SampledSpectrum<float>>> buildModel(  \
        const Model&, const MaterialBuilder<SampledSpectrum<float>>&);         \
    extern template std::unique_ptr<Bxdf<SampledSpectrum<double>>> buildModel( \
        const Model&, const MaterialBuilder<SampledSpectrum<double>>&);

LAMINA_EXTERN_BSDF_VARIANTS(MaterialBuilder)
extern template class MicrofacetDistribution<float>;
extern template class MicrofacetDistribution<double>;

}  // namespace lamina
