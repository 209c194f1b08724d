// The scatter step every integrator takes at a surface (camera paths of path and bdpt, light
// paths of light and bdpt): sample the BSDF, keep the direction only when the shading frame
// and the geometric surface agree on its side (shading_normals.h), update the throughput by
// the integrator's rule, play Russian roulette and spawn the next ray. The sampler's numbers
// are drawn in one order everywhere: the lobe choice (1D; skipped, not computed, for a BSDF
// that does not read it), the direction (2D), then, for a direction kept, the roulette (1D;
// skipped while the roulette cannot end the path).
#pragma once

#include <optional>

#include "lamina/core/ray.h"
#include "lamina/integrators/shading_normals.h"
#include "lamina/integrators/visibility.h"

namespace lamina::render {

/// Russian roulette once `bounces` reaches `rrDepth`: the path survives with probability
/// min(1, rrBeta) (rrBeta: its throughput relative to its start) and its throughput is divided
/// by that probability. Returns false when the path ends.
/// Whether Russian roulette can end the path at all (else it uses no random number).
inline bool rouletteApplies(float rrBeta, int bounces, int rrDepth) {
    return bounces >= rrDepth && !(rrBeta >= 1.0f);
}

template <SpectrumType S>
bool russianRoulette(S& beta, float rrBeta, int bounces, int rrDepth, float u) {
    if (!rouletteApplies(rrBeta, bounces, rrDepth)) return true;
    const float q = std::max(0.0f, 1.0f - rrBeta);
    if (u < q) return false;
    beta /= 1.0f - q;
    return true;
}

/// A surface point a path arrived at: its normals, the shading frame, the direction back
/// to where the path came from (world and shading frame), and the geometry's ray offset
/// scale (ray_offset.h) for the ray that leaves it. A curve's tangent (SurfaceHit::tangent)
/// turns the frame's x along the fibre; without one (zero) the frame follows the normal.
struct ShadingPoint {
    ShadingPoint(const Vec3f& p_, const Vec3f& ng_, const Vec3f& ns_, const Vec3f& woWorld_,
                 float offsetScale_, const Vec3f& tangent = Vec3f(0.0f))
        : p(p_),
          ng(ng_),
          ns(ns_),
          frame(Frame<float>::fromNormalTangent(ns_, tangent)),
          woWorld(woWorld_),
          wo(frame.toLocal(woWorld_)),
          offsetScale(offsetScale_) {}

    Vec3f p, ng, ns;
    Frame<float> frame;
    Vec3f woWorld;  ///< unit, towards the previous vertex
    Vec3f wo;       ///< woWorld in the shading frame
    float offsetScale;
};

template <SpectrumType S>
struct ScatterResult {
    std::optional<BsdfSample<S>> sample;  ///< what the BSDF returned, even if the path ends
    std::optional<Ray> next;              ///< the ray the path goes on along; none: it ends
};

/// The path at `at` (`bounces` surfaces so far, this one included) scatters in `mode`.
/// `updateThroughput(beta, sample, wi)` (wi the world direction) applies the integrator's
/// rule to the throughput and returns what Russian roulette compares with 1: the throughput
/// relative to the path's start.
template <SpectrumType S, typename UpdateThroughput>
ScatterResult<S> scatter(const Bxdf<S>& bsdf, const ShadingPoint& at, TransportMode mode,
                         int bounces, int rrDepth, PixelSampler& sampler, S& beta,
                         UpdateThroughput&& updateThroughput) {
    ScatterResult<S> result;
    const float uc = sampler.get1DIfUsed(bsdf.usesLobeChoice());
    const Vec2f u = sampler.get2D();
    result.sample = bsdf.sample(at.wo, uc, u, mode);
    const auto& s = result.sample;
    if (!s || !(s->pdf > 0.0f)) return result;
    const Vec3f wi = at.frame.toWorld(s->wi);
    // A direction on the wrong side of the geometric surface for its lobe (possible with
    // shading normals) would leak light through the surface.
    if (!sidesAgree(at.woWorld, wi, at.ng, at.ns)) return result;
    const float rrBeta = updateThroughput(beta, *s, wi);
    // The roulette's number is computed only when the roulette can end the path; otherwise
    // its dimension is skipped, so the numbers after it are the same either way.
    if (rouletteApplies(rrBeta, bounces, rrDepth)) {
        if (!russianRoulette(beta, rrBeta, bounces, rrDepth, sampler.get1D())) return result;
    } else {
        sampler.skip();
    }
    if (!beta.isFinite() || beta.maxValue() <= 0.0f) return result;
    result.next = Ray(offsetRayOrigin(at.p, facing(at.ng, wi), at.offsetScale), wi);
    return result;
}

}  // namespace lamina::render
