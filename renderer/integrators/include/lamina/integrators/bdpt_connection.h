// BDPT's connection step: the contribution of strategy (s, t), s light vertices and t camera
// vertices (Veach 1997, section 10.2):
//   s = 0       the camera subpath's end is an emitter (or escaped to an infinite light);
//   s = 1       next-event estimation from camera vertex t-1 (a fresh light sample);
//   t = 1       light vertex s-1 connected to the lens (light tracing), to be splatted;
//   s, t >= 2   a deterministic connection of the two subpath ends, with a shadow ray.
// Light-subpath vertices evaluate the adjoint BSDF with the shading-normal correction
// (transport_ablations.h), camera-subpath vertices the BSDF. A contribution is the camera
// prefix, the connection and the light prefix multiplied in that order, which the polarised
// mode's matrices need (docs/polarisation.md, "Light paths").
// Through media (docs/media.md) either end may be a medium vertex, which scatters by its
// phase function; a connection's segment carries its exact transmittance, traced through
// every index-matched interface on its way, and a contribution is divided by the average over
// the channels of its two subpaths' density ratios (the spectral MIS of medium_transport.h).
// A medium's emission (docs/media.md) is counted at a camera subpath's medium vertex (s = 0) and
// from a light subpath that starts in the medium's volume (s >= 1).
#pragma once

#include <optional>
#include <vector>

#include "lamina/integrators/bdpt_mis.h"
#include "lamina/integrators/grid_tracking.h"

namespace lamina::render {

/// What a connection gives: zero, or the unweighted contribution and its MIS weight.
template <SpectrumType S>
struct BdptConnection {
    S contribution{0.0f};  ///< unweighted
    float misWeight = 0.0f;
    Vec2f splatAt{0.0f};  ///< the film position of a t = 1 strategy
    Vec3f toLens{0.0f};   ///< t = 1: the direction the light reaches the lens along
};

template <SpectrumType S>
class BdptConnector {
  public:
    using Mode = RenderMode<S>;
    using Vertex = BdptVertex<S>;

    BdptConnector(const SceneContext& context, const Mode& mode,
                  const TransportAblations& ablations, const BdptMisWeights<S>& mis)
        : c_(context),
          mode_(mode),
          ablations_(ablations),
          mis_(mis),
          media_(Mode::kRendersMedia && context.scene.hasMedia()) {}

    /// Strategy (s, t) of the two subpaths; s = 1 and t = 1 draw their fresh vertex from
    /// `sampler` (a light point: 1D + 2D; a lens point: 2D). `hero`: the subpaths' hero channel
    /// (with media), which tracks the connection through grid media.
    BdptConnection<S> connect(const std::vector<Vertex>& lightPath, int s,
                              const std::vector<Vertex>& cameraPath, int t, int hero,
                              PixelSampler& sampler, typename Mode::Path& path,
                              PathStatistics& stats) const;
    /// Strategy (1, t) of a light subpath that starts in an emitting medium's volume: its
    /// first vertex itself joined to camera vertex t - 1 (next-event estimation cannot sample
    /// a medium's emission; this is Veach's s = 1 with the particle's own point).
    BdptConnection<S> connectVolumeLight(const std::vector<Vertex>& lightPath,
                                         const std::vector<Vertex>& cameraPath, int t, int hero,
                                         typename Mode::Path& path, PathStatistics& stats) const;

  private:
    S evalAt(const Vertex& v, const Vec3f& wPrev, const Vec3f& wNext, bool lightSubpath,
             typename Mode::Path& path) const;
    S emitted(const Vertex& v, const Vec3f& w, const Vec3f& receiver,
              typename Mode::Path& path) const;
    /// Whether light passes between `from` and `to` (a point, or a direction when infinite),
    /// and with media the transmittance of the segment, which starts in the medium on the side
    /// of `from` it leaves to (`before`: the vertex its subpath came to `from` from; none for
    /// a lens); without media 1 when nothing blocks it.
    std::optional<Transmittance<S>> passes(const Vertex& from, const Vertex* before,
                                           const Vertex& to, int hero, typename Mode::Path& path,
                                           PathStatistics& stats) const;
    /// With media: `value` times the connection's transmittance `T`, over the average of the
    /// product of the density ratios of the two subpaths' last vertices and of the connection's
    /// ratio tracking (1 through homogeneous media; the balance heuristic over the channels,
    /// or the `hero`'s density alone with the ablation: TransportAblations::channelDensity);
    /// without, `value`.
    S throughMedia(const S& value, const Transmittance<S>& T, const S& rUCamera, const S& rULight,
                   int hero) const;

    SceneContext c_;
    const Mode& mode_;
    TransportAblations ablations_;
    const BdptMisWeights<S>& mis_;
    bool media_;  ///< the scene has media and the mode renders them
};

}  // namespace lamina::render
