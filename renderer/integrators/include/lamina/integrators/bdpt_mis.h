// BDPT's multiple importance sampling: the weight of strategy (s, t) among every strategy that
// could have produced the same path (power heuristic, beta = 2; balance as an option), from
// the ratios of the forward and reverse area densities stored on the vertices, in O(s + t)
// (Veach 1997, section 10.2.3, eq. 10.9), and the densities it needs: of a vertex sampling
// the next, and of a light subpath starting where it does. Delta lobes and delta lights have
// no density and are skipped as connection points.
#pragma once

#include <vector>

#include "lamina/integrators/bdpt_vertex.h"
#include "lamina/integrators/integrator.h"
#include "lamina/integrators/medium_emitters.h"

namespace lamina::render {

template <SpectrumType S>
class BdptMisWeights {
  public:
    using Mode = RenderMode<S>;
    using Vertex = BdptVertex<S>;

    /// `emitters`: the emitting media light subpaths start from too (must outlive this).
    BdptMisWeights(const SceneContext& context, const Mode& mode, MisHeuristic heuristic,
                   const MediumEmitters& emitters)
        : c_(context), mode_(mode), heuristic_(heuristic), emitters_(emitters) {}

    /// The weight of strategy (s, t); `sampled` is the connection's fresh vertex (the light
    /// point of s = 1, the lens point of t = 1).
    float weight(const std::vector<Vertex>& lightPath, int s, const std::vector<Vertex>& cameraPath,
                 int t, const Vertex& sampled, typename Mode::Path& path) const;

    /// Density with which a light subpath starts at light vertex `v` (or, for a camera
    /// subpath's Medium vertex, in the medium's volume there: per unit volume).
    float pdfLightOrigin(const Vertex& v) const;
    /// Density (area measure at `next`) with which a light subpath starting at light vertex
    /// `v` reaches `next`.
    float pdfLight(const Vertex& v, const Vertex& next) const;

  private:
    /// Whether `v`, as the path's light end, is a point of an emitting medium's volume.
    static bool inVolume(const Vertex& v) { return v.volume || v.type == BdptVertexType::Medium; }
    /// The factor that turns a camera subpath's area density of reaching volume point `v` into
    /// a density per unit volume: the channels' average extinction there (docs/media.md).
    float volumeFactor(const Vertex& v, typename Mode::Path& path) const;
    float infiniteLightDensity(const Vec3f& direction) const;
    /// How much likelier next-event estimation at `receiver` chooses the light of
    /// `lightVertex` than a particle starts from it.
    float selectionRatio(const Vertex& lightVertex, const Vertex& receiver) const;
    float pdf(const Vertex& v, const Vertex* prev, const Vertex& next,
              typename Mode::Path& path) const;

    SceneContext c_;
    const Mode& mode_;
    MisHeuristic heuristic_;
    const MediumEmitters& emitters_;
};

}  // namespace lamina::render
