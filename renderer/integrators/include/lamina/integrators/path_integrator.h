// The `path` integrator: camera path tracing with next-event estimation and BSDF sampling
// combined by multiple importance sampling (Veach 1997, ch. 9, power heuristic), emission
// hit by BSDF sampling weighted the same way, Russian roulette on throughput, delta lobes and
// delta lights handled. The same code runs in every render mode. With `next_event` false
// (RenderSettings::nextEvent) BSDF sampling is the only strategy: a reference that no light
// sample and no MIS weight touches (delta lights, which no ray hits, then light nothing).
#pragma once

#include "lamina/integrators/integrator.h"
#include "lamina/integrators/scatter.h"

namespace lamina::render {

template <SpectrumType S>
class PathIntegrator final : public Integrator<S> {
  public:
    using Mode = RenderMode<S>;

    explicit PathIntegrator(const IntegratorSetup<S>& setup);

    bool splats() const override { return false; }
    std::optional<CameraEstimate<S>> sample(const PixelSample<S>& sample) const override;

  private:
    /// Radiance along a camera ray. `aovs` (optional) receives first-hit data.
    S radiance(const Vec3f& rayOrigin, const Vec3f& rayDirection, PixelSampler& sampler,
               typename Mode::Path& path, PathStatistics& stats, PixelAovs* aovs) const;
    /// Next-event estimation at `at`: one light sample, weighted against BSDF sampling.
    S directLight(const SurfaceHit& hit, const ShadingPoint& at, const Bxdf<S>& bsdf, float uLight,
                  const Vec2f& uPoint, typename Mode::Path& path, PathStatistics& stats) const;

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    bool aovs_;
};

}  // namespace lamina::render
