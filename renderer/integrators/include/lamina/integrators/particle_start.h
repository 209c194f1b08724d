// The start of a light particle (light tracing, BDPT's light subpaths): choose a light, sample
// a point and a direction of its emission, and the throughput the particle starts with,
//   beta = Le |cos(normal, direction)| / (p_light pdfPosition pdfDirection)
// (Veach 1997, section 10.2). The sampler's numbers: the light (1D), the position (2D), the
// direction (2D), drawn even when the scene has no light. In a scene with emitting media a
// particle may start in a medium's volume instead (medium_emitters.h), with
//   beta = sigma_a(x) Le / (P p(x) (1 / 4 pi)),
// x of density p per unit volume, its direction uniform on the sphere; the choice then always
// reads its number, and one more number follows the direction's (the point's third coordinate).
#pragma once

#include <optional>

#include "lamina/integrators/integrator.h"
#include "lamina/integrators/medium_emitters.h"

namespace lamina::render {

template <SpectrumType S>
struct ParticleStart {
    std::size_t light;        ///< the chosen light's index
    float pmf;                ///< the probability it was chosen with
    EmissionSample emission;  ///< where and in which direction the particle leaves
    bool onSurface;           ///< leaves a surface (an area light): a point the camera can see
    S beta;                   ///< the throughput it starts with
    Vec3f origin;             ///< of its first ray (moved off the surface when on one)
    /// A particle of a medium's emission: the medium (into SceneDesc::media; `light` unused,
    /// `emission` holds its point, a zero normal, its direction and densities, per unit volume
    /// and solid angle); -1: a light's particle.
    int medium = -1;
    S volumeEmission{0.0f};  ///< such a particle's sigma_a(x) Le at its origin
};

/// The particle of this sample, or nothing when the emission sample failed or carries nothing.
template <SpectrumType S>
std::optional<ParticleStart<S>> startParticle(const LightSet& lights, const Geometry& geometry,
                                              const RenderMode<S>& mode, PixelSampler& sampler,
                                              typename RenderMode<S>::Path& path,
                                              const MediumEmitters& emitters);

}  // namespace lamina::render
