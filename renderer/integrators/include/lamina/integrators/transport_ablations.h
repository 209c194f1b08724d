// Known mistakes of other renderers, reproducible on purpose (lamina reciprocity --ablate):
// with one of them on, light tracing and BDPT no longer agree with camera tracing. The light
// paths of both integrators ask these helpers for their transport mode, their BSDF at a
// connection and their shading-normal factor, so each mistake is switched in one place.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/integrators/shading_normals.h"

namespace lamina::render {

struct TransportAblations {
    bool noAdjointCorrection = false;   ///< drop the shading-normal factor (pbrt-v3 #73)
    bool radianceOnLightPaths = false;  ///< the 1/eta^2 rule on light paths (pbrt-v4 #30)
    bool swappedConnections = false;    ///< f(wi, wo) at light-path connections (pbrt-v4 #395)

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
};

}  // namespace lamina::render
