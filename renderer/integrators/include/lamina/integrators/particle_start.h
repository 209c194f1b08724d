// The start of a light particle (light tracing, BDPT's light subpaths): choose a light, sample
// a point and a direction of its emission, and the throughput the particle starts with,
//   beta = Le |cos(normal, direction)| / (p_light pdfPosition pdfDirection)
// (Veach 1997, section 10.2). The sampler's numbers: the light (1D), the position (2D), the
// direction (2D), drawn even when the scene has no light.
#pragma once

#include <optional>

#include "lamina/integrators/integrator.h"

namespace lamina::render {

template <SpectrumType S>
struct ParticleStart {
    std::size_t light;        ///< the chosen light's index
    float pmf;                ///< the probability it was chosen with
    EmissionSample emission;  ///< where and in which direction the particle leaves
    bool onSurface;           ///< leaves a surface (an area light): a point the camera can see
    S beta;                   ///< the throughput it starts with
    Vec3f origin;             ///< of its first ray (moved off the surface when on one)
};

/// The particle of this sample, or nothing when the emission sample failed or carries nothing.
template <SpectrumType S>
std::optional<ParticleStart<S>> startParticle(const LightSet& lights, const Geometry& geometry,
                                              const RenderMode<S>& mode, PixelSampler& sampler,
                                              typename RenderMode<S>::Path& path);

}  // namespace lamina::render
