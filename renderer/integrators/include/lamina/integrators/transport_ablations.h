// Known mistakes of other renderers, reproducible on purpose (lamina reciprocity --ablate):
// with one of them on, light tracing and BDPT no longer agree with camera tracing. The light
// paths of both integrators ask these helpers for their transport mode, their BSDF at a
// connection and their shading-normal factor, so each mistake is switched in one place.
//
// And one ablation that is no mistake but a worse estimator (`lamina media`, `lamina render
// --ablate media-spectral-mis`): the spectral MIS over the channels of paths through media
// switched off (channelDensity), so that its gain can be measured.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/name_table.h"
#include "lamina/integrators/shading_normals.h"

namespace lamina::render {

struct TransportAblations {
    bool noAdjointCorrection = false;   ///< drop the shading-normal factor (pbrt-v3 #73)
    bool radianceOnLightPaths = false;  ///< the 1/eta^2 rule on light paths (pbrt-v4 #30)
    bool swappedConnections = false;    ///< f(wi, wo) at light-path connections (pbrt-v4 #395)
    /// Every channel of a path through media weighted by its hero channel's density alone
    /// (channelDensity): Mitsuba 2's `volpath`, its issue #323. Unbiased where every channel's
    /// extinction is above zero wherever another's is, but each channel's estimate carries
    /// T_c / T_h, heavy-tailed in a chromatic medium; all three integrators.
    bool noMediaSpectralMis = false;

    /// The mode light paths evaluate and sample their BSDFs in: importance (the adjoint BSDF).
    TransportMode lightPathMode() const {
        return radianceOnLightPaths ? TransportMode::Radiance : TransportMode::Importance;
    }

    /// The adjoint shading-normal factor of a light-path vertex (shading_normals.h); wo
    /// towards the light's side, wi where the particle goes.
    float adjointCorrection(const Vec3<float>& wo, const Vec3<float>& wi, const Vec3<float>& ng,
                            const Vec3<float>& ns) const {
        if (noAdjointCorrection) return 1.0f;
        return adjointShadingCorrection(wo, wi, ng, ns);
    }

    /// The BSDF of a light-path vertex connected to another subpath, in the shading frame:
    /// wo towards the light's side, wi towards the connected vertex.
    template <SpectrumType S>
    S connectionBsdf(const Bxdf<S>& bsdf, const Vec3<float>& wo, const Vec3<float>& wi) const {
        const TransportMode mode = lightPathMode();
        return swappedConnections ? bsdf.eval(wi, wo, mode) : bsdf.eval(wo, wi, mode);
    }

    /// What an estimate through media is divided by, relative to the hero channel's density
    /// (medium_transport.h): the average over the channels of their densities `ratios` (each
    /// relative to the hero's), the one-sample balance heuristic over the channel strategies
    /// (Miller, Georgiev and Jarosz 2019, section 5.2); with noMediaSpectralMis the hero's own,
    /// ratios[hero] (1 on a path's own ratios): the hero's strategy alone.
    template <SpectrumType S>
    float channelDensity(const S& ratios, int hero) const {
        return noMediaSpectralMis ? ratios[hero] : ratios.average();
    }
};

/// The ablations a render takes (`lamina render --ablate`, lamina.render(ablate=...)): worse
/// estimators on purpose, not wrong ones (the mistakes are `lamina reciprocity --ablate`'s).
enum class RenderAblation { MediaSpectralMis };
inline constexpr NameTable kRenderAblationNames{
    std::array{NameEntry{RenderAblation::MediaSpectralMis, "media-spectral-mis"}}};

/// Switches `ablation` on in `ablations`.
inline void applyRenderAblation(RenderAblation ablation, TransportAblations& ablations) {
    switch (ablation) {
        case RenderAblation::MediaSpectralMis:
            ablations.noMediaSpectralMis = true;
            break;
    }
}

}  // namespace lamina::render
