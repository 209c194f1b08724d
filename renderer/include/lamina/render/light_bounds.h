// What the light BVH (light_bvh.h) knows of a light or of a cluster of lights: where it is
// (an axis-aligned box), which way it emits (a cone of normals widened by the spread of
// emission about each normal) and how strong it is; and the importance a cluster has as seen
// from a shading point. Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights
// with Adaptive Tree Splitting" (section 4.1, the orientation bounds and eq. 3, the
// importance), with pbrt-v4's normal term at the receiver (LightBounds::Importance).
#pragma once

#include "lamina/core/vector.h"

namespace lamina::render {

struct LightBounds {
    Vec3f lower{0.0f}, upper{0.0f};  ///< the box of the emitting points
    Vec3f axis{0.0f, 0.0f, 1.0f};    ///< unit; every emitting normal is within theta_o of it
    float cosThetaO = 1.0f;          ///< cos(theta_o), -1: normals in every direction
    /// cos(theta_e): emission leaves at most theta_e from its normal (pi/2 for surfaces; the
    /// width of the smoothstep band beyond theta_o for a spot light).
    float cosThetaE = 0.0f;
    /// The largest radiant intensity the light has (W/sr, RGB luminance): I for a light at a
    /// point, L A for a flat surface seen face-on, L pi r^2 for a sphere; summed over a
    /// cluster. Importance is this times the cosines over the squared distance.
    float intensity = 0.0f;
    bool twoSided = false;  ///< emits about -axis as well (two-sided surfaces)

    Vec3f center() const { return 0.5f * (lower + upper); }
    /// Importance at point `p` with surface normal `n` (zero vector: no surface, such as a
    /// point in a medium): 0 only when no light of the cluster can send light to p.
    float importance(const Vec3f& p, const Vec3f& n) const;
};

/// The bounds of two clusters together: the union of the boxes, the smallest cone of normals
/// holding both cones (Conty Estevez and Kulla 2018, Algorithm 1), the larger theta_e and the
/// summed intensity.
LightBounds unite(const LightBounds& a, const LightBounds& b);

/// The cone of normals' solid-angle measure M_Omega, weighted by the cosine of emission
/// (Conty Estevez and Kulla 2018, eq. 1), the orientation factor of the split cost.
float orientationMeasure(const LightBounds& b);

}  // namespace lamina::render
