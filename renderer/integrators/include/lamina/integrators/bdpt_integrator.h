// The `bdpt` integrator: Veach's bidirectional path tracer (Veach 1997, chapter 10; Veach and
// Guibas 1995). Per camera sample it traces a camera subpath and a light subpath (vertices:
// bdpt_vertex.h) and combines every (s, t) connection, s light vertices and t camera vertices
// (bdpt_connection.h), each weighted by multiple importance sampling over all strategies that
// could have produced the same path (bdpt_mis.h). The t >= 2 strategies give the camera
// sample's value, the t = 1 strategies are splatted. Light subpaths use the adjoint BSDF with
// the shading-normal correction (shading_normals.h), camera subpaths the BSDF.
// Through homogeneous media (docs/media.md) both subpaths sample free flights with one hero
// channel per camera sample and scatter at medium vertices by the Henyey-Greenstein phase
// function; connections carry the exact transmittance of their segment; a contribution is
// divided by the average over the channels of its subpaths' densities relative to the hero's
// (the spectral MIS of medium_transport.h), the strategies weighted as without media. A medium's
// emission is a light source (medium_emitters.h): light subpaths may start in its volume, and
// camera subpaths count it at their medium vertices (docs/media.md).
#pragma once

#include <vector>

#include "lamina/integrators/bdpt_connection.h"

namespace lamina::render {

template <SpectrumType S>
class BdptIntegrator final : public Integrator<S> {
  public:
    using Mode = RenderMode<S>;
    using Vertex = BdptVertex<S>;

    explicit BdptIntegrator(const IntegratorSetup<S>& setup);

    bool splats() const override { return true; }
    std::optional<CameraEstimate<S>> sample(const PixelSample<S>& sample) const override;

  private:
    /// Returns the camera ray's direction.
    Vec3f generateCameraSubpath(const CameraSample& cs, PixelSampler& sampler,
                                typename Mode::Path& path, int hero, std::vector<Vertex>& out,
                                PathStatistics& stats) const;
    void generateLightSubpath(PixelSampler& sampler, typename Mode::Path& path, int hero,
                              std::vector<Vertex>& out, PathStatistics& stats) const;
    /// Where a subpath's walk starts: its ray, throughput and the solid-angle density of the
    /// ray's direction, the medium the ray starts in (-1: vacuum) and the hero channel of the
    /// camera sample's free flights.
    struct WalkStart {
        Vec3f o, d;
        S beta;
        float pdfDir;
        int medium, hero;
        S rU{1.0f};  ///< the subpath's densities per channel so far (medium_transport.h)
    };
    /// Extends a subpath from its last vertex until `maxVertices` vertices are added.
    void randomWalk(WalkStart start, int maxVertices, TransportMode mode, PixelSampler& sampler,
                    typename Mode::Path& path, std::vector<Vertex>& out,
                    PathStatistics& stats) const;
    /// Records a contribution of strategy (s, t) in the strategy images, if they are kept.
    void recordStrategy(int s, int t, const Rgb<double>& weighted, const Rgb<double>& unweighted,
                        const Vec2f& splatAt, int px, int py, float filterWeight) const;

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    TransportAblations ablations_;
    StrategyImages* strategies_;
    bool media_;  ///< the scene has media (SceneDesc::hasMedia) and the mode renders them
    MediumEmitters emitters_;  ///< the emitting media light subpaths also start from
    BdptMisWeights<S> mis_;
    BdptConnector<S> connector_;
};

}  // namespace lamina::render
