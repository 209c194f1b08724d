// The `path` integrator: camera path tracing with next-event estimation and BSDF sampling
// combined by multiple importance sampling (Veach 1997, ch. 9, power heuristic), emission
// hit by BSDF sampling weighted the same way, Russian roulette on throughput, delta lobes and
// delta lights handled. The same code runs in every render mode. With `next_event` false
// (RenderSettings::nextEvent) BSDF sampling is the only strategy: a reference that no light
// sample and no MIS weight touches (delta lights, which no ray hits, then light nothing).
// Through media (docs/media.md): free flights sampled by a hero channel (delta tracking in grid
// media) with
// spectral MIS over the channels, Henyey-Greenstein scattering, next-event estimation through
// the media and interfaces on the way, emission in the media (medium_transport.h); there, light
// and scattering samples are combined by the balance heuristic over strategies and channels
// together (pbrt-v4's VolPathIntegrator). A scene without media takes exactly the code of
// before.
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
    /// Where next-event estimation starts: a surface point (`shape` set, normals ng and ns),
    /// or a point in a medium (no shape, zero normals), with the medium the path is in there,
    /// the direction it arrived along and the path's hero channel (medium_transport.h).
    struct Vertex {
        Vec3f p, ng, ns;
        const ShapeInfo* shape;
        int medium;
        Vec3f arrival;
        int hero;
    };
    /// Next-event estimation at `v`: one light sample, weighted against sampling the vertex's
    /// scattering. `value(wi)` is the scattering's f |cos| (the phase function in a medium),
    /// zero for a direction it refuses; `density(wi)` its sampling density. In a scene with
    /// media, `pathRatios` are the path's densities per channel relative to its hero's
    /// (medium_transport.h).
    template <typename Value, typename Density>
    S directLight(const Vertex& v, Value&& value, Density&& density, const S& pathRatios,
                  float uLight, const Vec2f& uPoint, typename Mode::Path& path,
                  PathStatistics& stats) const;

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    bool aovs_;
    TransportAblations ablations_;  ///< of media: the spectral MIS over the channels, or not
    bool media_;  ///< the scene has media (SceneDesc::hasMedia) and the mode renders them
};

}  // namespace lamina::render
