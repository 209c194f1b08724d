// Shading normals and the transport they break (Veach 1997, section 5.3). Two rules, the same
// in every integrator, so that camera tracing, light tracing and BDPT estimate one integral:
//  - a pair of directions scatters only when the shading frame and the geometric surface agree
//    on whether it is a reflection or a transmission (otherwise light would leak through the
//    surface); the BSDF counts as zero for the pair;
//  - on light subpaths the adjoint BSDF with shading normals is not the BSDF with its arguments
//    swapped: it carries the factor |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|) (Veach eq. 5.17), with
//    wo towards the light's side and wi where the particle goes. Without it light tracing
//    disagrees with camera tracing on smooth-shaded meshes (pbrt-v3 issue 73).
#pragma once

#include <cmath>

#include "lamina/core/vector.h"

namespace lamina::render {

/// wo, wi: unit, both pointing away from the surface; ng, ns on the same side.
inline bool sidesAgree(const Vec3<float>& wo, const Vec3<float>& wi, const Vec3<float>& ng,
                       const Vec3<float>& ns) {
    const float geometric = glm::dot(wo, ng) * glm::dot(wi, ng);
    const float shading = glm::dot(wo, ns) * glm::dot(wi, ns);
    if (geometric == 0.0f || shading == 0.0f) return false;
    return (geometric > 0.0f) == (shading > 0.0f);
}

/// The factor the adjoint BSDF (importance transport) carries with shading normals; wo is the
/// direction towards the previous vertex of the light subpath, wi the next one.
inline float adjointShadingCorrection(const Vec3<float>& wo, const Vec3<float>& wi,
                                      const Vec3<float>& ng, const Vec3<float>& ns) {
    const float denominator = std::abs(glm::dot(wo, ng) * glm::dot(wi, ns));
    if (!(denominator > 0.0f)) return 0.0f;
    return std::abs(glm::dot(wo, ns) * glm::dot(wi, ng)) / denominator;
}

}  // namespace lamina::render
