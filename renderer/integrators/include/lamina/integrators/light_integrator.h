// The `light` integrator: light tracing (particle tracing). Particles leave the lights with
// their emission densities, scatter with the BSDFs evaluated and sampled in importance mode
// (the adjoint BSDF: the direction light flows, no 1/eta^2 on refraction) with the adjoint
// shading-normal correction, and every vertex is connected to the camera and splatted on the
// film (Veach 1997, sections 10.2 and 10.8). Delta lobes cannot be connected; delta lights are
// sampled like the others. Infinite lights seen directly cannot be reached by a particle (the
// lens has no area facing infinity); they are missing from this integrator's images.
// Through homogeneous media (docs/media.md) a particle samples free flights with the path
// integrator's spectral MIS (medium_transport.h), scatters by the Henyey-Greenstein phase
// function at medium vertices and connects every vertex, surface or medium, to the camera with
// the exact transmittance of the connection. Particles start from the emitting media too
// (medium_emitters.h), from points of their volumes.
#pragma once

#include "lamina/integrators/integrator.h"
#include "lamina/integrators/medium_emitters.h"

namespace lamina::render {

template <SpectrumType S>
class LightIntegrator final : public Integrator<S> {
  public:
    using Mode = RenderMode<S>;

    explicit LightIntegrator(const IntegratorSetup<S>& setup);

    bool splats() const override { return true; }
    /// One particle per pixel sample (seeded by the pixel); it only splats.
    std::optional<CameraEstimate<S>> sample(const PixelSample<S>& sample) const override;

  private:
    /// Traces one particle and splats its contributions (to be scaled by 1 / particles).
    void traceParticle(PixelSampler& sampler, typename Mode::Path& path, Film& film,
                       PathStatistics& stats) const;
    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    TransportAblations ablations_;
    bool media_;  ///< the scene has media (SceneDesc::hasMedia) and the mode renders them
    MediumEmitters emitters_;  ///< the emitting media particles also start from
};

}  // namespace lamina::render
