// Shadow rays: the side of a surface a direction leaves on, and whether a segment or a ray to
// infinity is unblocked. Every connection of every integrator (next-event estimation, camera
// connections, BDPT's deterministic connections) tests visibility through these two.
#pragma once

#include <limits>

#include "lamina/geometry/geometry.h"
#include "lamina/integrators/integrator.h"
#include "lamina/geometry/ray_offset.h"

namespace lamina::render {

/// The side of a surface a direction leaves on: the normal flipped to face `w`.
inline Vec3f facing(const Vec3f& n, const Vec3f& w) {
    return glm::dot(n, w) >= 0.0f ? n : -n;
}

/// True when nothing blocks the ray from surface point `p` (normal `n`) along `direction` to
/// infinity (an infinite light).
inline bool directionUnoccluded(const Geometry& geometry, const Vec3f& p, const Vec3f& n,
                                const Vec3f& direction, PathStatistics& stats) {
    ++stats.rays;
    return !geometry.occluded(offsetRayOrigin(p, facing(n, direction), geometry.rayOffsetScale()),
                              direction, std::numeric_limits<float>::infinity());
}

/// True when nothing blocks the segment between two points, each moved off its surface along
/// its normal on the side facing the other (a zero normal: a point not on a surface, such as
/// a lens or a point light, is not moved).
inline bool segmentUnoccluded(const Geometry& geometry, const Vec3f& a, const Vec3f& na,
                              const Vec3f& b, const Vec3f& nb, PathStatistics& stats) {
    const Vec3f ab = b - a;
    const float scale = geometry.rayOffsetScale();
    const Vec3f from = na == Vec3f(0.0f) ? a : offsetRayOrigin(a, facing(na, ab), scale);
    const Vec3f to = nb == Vec3f(0.0f) ? b : offsetRayOrigin(b, facing(nb, -ab), scale);
    const Vec3f segment = to - from;
    const float length = glm::length(segment);
    if (!(length > 0.0f)) return true;
    ++stats.rays;
    return !geometry.occluded(from, segment / length, length * (1.0f - 1e-4f));
}

}  // namespace lamina::render
