// `standard` and `layered` (standard_reader.cpp): the description both read into and how it
// builds the layered stack (layered.h): the article's material (section 4.3.1) and its
// generalisations, docs/bsdf.md.
#pragma once

#include "lamina/bsdf/layered.h"

namespace lamina {

/// `standard` and `layered` (standard_reader.cpp): the article's material (and its
/// generalisations); see docs/bsdf.md.
struct StandardMaterial {
    ColorInput baseColor{RgbInput(0.8)};
    double metalness = 0;
    double specular = 0.04;                 ///< F0 of the dielectric part
    std::optional<RgbInput> specularColor;  ///< specular workflow: F0 directly
    std::optional<RgbInput> f82;            ///< absolute reflectance at cos = 1/7
    std::optional<RgbInput> f82Tint;        ///< multiplier of Schlick at cos = 1/7
    double transmission = 0;
    double ior = 1.5;
    std::optional<DiffuseModel> diffuse = DiffuseModel::Lambert;  ///< nullopt: none
    bool specularLobe = true;
    bool phong = false;  ///< the article's Phong lobe instead of a microfacet one
    /// Perceptual roughness of the diffuse models (`layered` sets it; `standard` uses the
    /// specular roughness, as the article does).
    std::optional<double> diffuseRoughness;
    MicrofacetParams microfacet;
    FresnelChoice fresnel = FresnelChoice::SchlickShadowed;
    LayerCoupling coupling = LayerCoupling::Fresnel;
    /// Albedo coupling: the directional albedo of the specular interface (RGB average).
    std::shared_ptr<const AlbedoTable> interfaceAlbedo;
    /// `layered` with a conductor base: the conductor under the interface (its optics relative
    /// to the interface's medium of index `ior`), in place of the diffuse base.
    std::shared_ptr<const ConductorMaterial> conductorBase;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const StandardMaterial& s, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    const SpectrumContext<S>& ctx = b.context();
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
        if (!spectralBase || s.specularColor) return ctx.reflectance(f0rgb);
        return S(Float(s.specular * (1.0 - s.metalness))) +
               ctx.reflectance(s.baseColor) * Float(s.metalness);
    };
    const auto diffuseSpectrum = [&]() -> S {
        if (!spectralBase) return ctx.reflectance(diffuseRgb);
        return ctx.reflectance(s.baseColor) * Float(s.specularColor ? 1.0 : 1.0 - s.metalness);
    };

    typename LayeredBxdf<S>::Layers layers;
    layers.coupling = s.coupling;
    const auto dist = MaterialBuilder<S>::distribution(s.microfacet);
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
                    fresnel = Fresnel<S>::hoffmanF82(f0, ctx.reflectance(*s.f82));
                else
                    fresnel = Fresnel<S>::hoffmanF82Tint(
                        f0, ctx.unbounded(s.f82Tint.value_or(RgbInput(1.0))));
                break;
            case FresnelChoice::Exact:
                fresnel = Fresnel<S>::dielectric(S(Float(s.ior)));
                break;
            default:
                fresnel = Fresnel<S>::schlickShadowed(f0, MaterialBuilder<S>::shadowedF90(f0rgb));
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
        layers.conductorBase.emplace(buildConductorBxdf(*s.conductorBase, b),
                                     Float(s.specularLobe ? s.ior : 1.0));
    if (s.transmission > 0.0) {
        layers.transmission.emplace(Float(s.ior), dist, s.microfacet.g2);
        layers.transmissionWeight = Float(s.transmission);
    }
    return std::make_unique<LayeredBxdf<S>>(std::move(layers));
}
LAMINA_MATERIAL_MODEL(StandardMaterial)

}  // namespace lamina
