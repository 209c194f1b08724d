// What the three integrators (path, light, bdpt) share: the scene they read, their
// statistics, the MIS heuristics, and the deliberate mistakes an experiment can switch on.
#pragma once

#include "lamina/render/camera.h"
#include "lamina/render/lights.h"
#include "lamina/render/ray_offset.h"
#include "lamina/render/render_mode.h"
#include "lamina/render/shading_normals.h"

namespace lamina::render {

/// The power heuristic with beta = 2 (Veach 1997, eq. 9.13) for one sample of each strategy.
inline float powerHeuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    if (!std::isfinite(a2)) return 1.0f;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

struct SceneContext {
    const SceneDesc& scene;
    const Geometry& geometry;
    const LightSet& lights;
    const Camera& camera;
};

/// Known mistakes of other renderers, reproducible on purpose (lamina reciprocity --ablate):
/// with one of them on, light tracing and BDPT no longer agree with camera tracing.
struct TransportAblations {
    bool noAdjointCorrection = false;   ///< drop the shading-normal factor (pbrt-v3 #73)
    bool radianceOnLightPaths = false;  ///< the 1/eta^2 rule on light paths (pbrt-v4 #30)
    bool swappedConnections = false;    ///< f(wi, wo) at light-path connections (pbrt-v4 #395)
};

struct PathStatistics {
    std::uint64_t rays = 0;  ///< closest-hit and shadow rays traced
};

/// Russian roulette once `bounces` reaches `rrDepth`: the path survives with probability
/// min(1, rrBeta) (rrBeta: its throughput relative to its start) and its throughput is divided
/// by that probability. Returns false when the path ends.
template <SpectrumType S>
bool russianRoulette(S& beta, float rrBeta, int bounces, int rrDepth, float u) {
    if (bounces < rrDepth || rrBeta >= 1.0f) return true;
    const float q = std::max(0.0f, 1.0f - rrBeta);
    if (u < q) return false;
    beta /= 1.0f - q;
    return true;
}

/// The side of a surface a direction leaves on: the normal flipped to face `w`.
inline Vec3f facing(const Vec3f& n, const Vec3f& w) {
    return glm::dot(n, w) >= 0.0f ? n : -n;
}

/// True when nothing blocks the ray from surface point `p` (normal `n`) along `direction` to
/// infinity (an infinite light).
inline bool directionUnoccluded(const Geometry& geometry, const Vec3f& p, const Vec3f& n,
                                const Vec3f& direction, PathStatistics& stats) {
    ++stats.rays;
    return !geometry.occluded(offsetRayOrigin(p, facing(n, direction)), direction,
                              std::numeric_limits<float>::infinity());
}

/// True when nothing blocks the segment between two points, each moved off its surface along
/// its normal on the side facing the other (a zero normal: a point not on a surface, such as
/// a lens or a point light, is not moved).
inline bool segmentUnoccluded(const Geometry& geometry, const Vec3f& a, const Vec3f& na,
                              const Vec3f& b, const Vec3f& nb, PathStatistics& stats) {
    const Vec3f ab = b - a;
    const Vec3f from = na == Vec3f(0.0f) ? a : offsetRayOrigin(a, facing(na, ab));
    const Vec3f to = nb == Vec3f(0.0f) ? b : offsetRayOrigin(b, facing(nb, -ab));
    const Vec3f segment = to - from;
    const float length = glm::length(segment);
    if (!(length > 0.0f)) return true;
    ++stats.rays;
    return !geometry.occluded(from, segment / length, length * (1.0f - 1e-4f));
}

}  // namespace lamina::render
