// What the light BVH (light_bvh.h) knows of a light or of a cluster of lights: where it is
// (an axis-aligned box), which way it emits (a cone of normals widened by the spread of
// emission about each normal) and how strong it is; and the importance a cluster has as seen
// from a shading point. Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights
// with Adaptive Tree Splitting" (section 4.1, the orientation bounds and eq. 3, the
// importance), with pbrt-v4's normal term at the receiver (LightBounds::Importance).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "lamina/core/math.h"
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
    /// point in a medium): 0 only when no light of the cluster can send light to p
    /// (ImportanceBounds::importance, below).
    float importance(const Vec3f& p, const Vec3f& n) const;
};

/// LightBounds in the form the importance is computed from, with what depends on the bounds
/// alone (the centre, the bounding sphere's squared radius, sin theta_o) computed once: the
/// light BVH's nodes keep their bounds so, since choosing a light evaluates two importances per
/// level at every next-event estimate. importance() is defined here, inline, so that the
/// tree's two evaluations per level compile into one function; it is the only definition
/// (LightBounds::importance converts and calls it), so both give the same float.
struct ImportanceBounds {
    Vec3f center{0.0f};
    float radius2 = 0.0f;  ///< the squared radius of the box's bounding sphere
    Vec3f axis{0.0f, 0.0f, 1.0f};
    float cosThetaO = 1.0f, sinThetaO = 0.0f, cosThetaE = 0.0f;
    float intensity = 0.0f;
    bool twoSided = false;

    ImportanceBounds() = default;
    explicit ImportanceBounds(const LightBounds& b)
        : center(b.center()),
          radius2(0.25f * lengthSquared(b.upper - b.lower)),
          axis(b.axis),
          cosThetaO(b.cosThetaO),
          sinThetaO(safeSqrt(1.0f - b.cosThetaO * b.cosThetaO)),
          cosThetaE(b.cosThetaE),
          intensity(b.intensity),
          twoSided(b.twoSided) {}

    inline float importance(const Vec3f& p, const Vec3f& n) const;
};

/// The bounds of two clusters together: the union of the boxes, the smallest cone of normals
/// holding both cones (Conty Estevez and Kulla 2018, Algorithm 1), the larger theta_e and the
/// summed intensity.
LightBounds unite(const LightBounds& a, const LightBounds& b);

/// The cone of normals' solid-angle measure M_Omega, weighted by the cosine of emission
/// (Conty Estevez and Kulla 2018, eq. 1), the orientation factor of the split cost.
float orientationMeasure(const LightBounds& b);

namespace detail {

// cos(max(0, a - b)) and sin(max(0, a - b)) for angles a, b in [0, pi] given by their cosines
// and sines, without an acos.
inline float cosOfClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    if (cosA >= cosB) return 1.0f;
    return cosA * cosB + sinA * sinB;
}

inline float sinOfClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    if (cosA >= cosB) return 0.0f;
    return sinA * cosB - cosA * sinB;
}

inline float sinFromCos(float c) {
    return safeSqrt(1.0f - c * c);
}

}  // namespace detail

inline float ImportanceBounds::importance(const Vec3f& p, const Vec3f& n) const {
    using detail::cosOfClampedDifference, detail::sinOfClampedDifference, detail::sinFromCos;
    const Vec3f fromCenter = p - center;
    const float d2 = glm::dot(fromCenter, fromCenter);
    // theta_u: the half-angle of the cone from p that holds the cluster's bounding sphere (pi
    // when p is inside it, so every angle below clamps to 0).
    float cosU = -1.0f, sinU = 0.0f;
    if (d2 > radius2) {
        const float sin2U = radius2 / d2;
        cosU = safeSqrt(1.0f - sin2U);
        sinU = std::sqrt(sin2U);
    }
    const Vec3f w = d2 > 0.0f ? fromCenter / std::sqrt(d2) : Vec3f(0.0f);

    // theta' = max(0, theta - theta_o - theta_u), theta the angle between the axis and the
    // direction towards p (Conty Estevez and Kulla 2018, eq. 3); beyond theta_e no light of
    // the cluster can leave towards p.
    float cosTheta = glm::dot(axis, w);
    if (twoSided) cosTheta = std::abs(cosTheta);
    const float sinTheta = sinFromCos(cosTheta);
    const float cosX = cosOfClampedDifference(cosTheta, sinTheta, cosThetaO, sinThetaO);
    const float sinX = sinOfClampedDifference(cosTheta, sinTheta, cosThetaO, sinThetaO);
    const float cosThetaP = cosOfClampedDifference(cosX, sinX, cosU, sinU);
    if (cosThetaP <= cosThetaE) return 0.0f;

    // The distance is the centre's, but no less than half the bounding radius: near the
    // centre of a cluster its distance says little, and a point on a light would weigh
    // infinitely. (A bound of the whole radius, measured on scenes/many-lights.json, gives
    // 4x the variance: it makes every cluster around the point look equally far.)
    float value =
        intensity * cosThetaP / std::max({d2, 0.25f * radius2, std::numeric_limits<float>::min()});
    if (n != Vec3f(0.0f)) {
        // The receiver's cosine, |cos| so that transmission is not culled, at the smallest
        // angle a direction into the bounding sphere can make with n.
        const float cosI = std::abs(glm::dot(n, w));
        value *= cosOfClampedDifference(cosI, sinFromCos(cosI), cosU, sinU);
    }
    if (!(value > 0.0f)) return 0.0f;
    return std::min(value, std::numeric_limits<float>::max());
}

}  // namespace lamina::render
