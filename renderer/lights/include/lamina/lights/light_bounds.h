// What the light BVH (light_bvh.h) knows of a light or of a cluster of lights: where it is
// (an axis-aligned box), which way it emits (a cone of normals widened by the spread of
// emission about each normal) and how strong it is; and the importance a cluster has as seen
// from a shading point. Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights
// with Adaptive Tree Splitting" (section 4.1, the orientation bounds and eq. 3, the
// importance), with pbrt-v4's normal term at the receiver (LightBounds::Importance).
#pragma once

#include <array>
#include <cstddef>

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
/// alone (the centre, the bounding sphere's squared radius, sin theta_o) computed once.
/// importance() is the one definition of the importance (LightBounds::importance converts and
/// calls it; ImportancePair computes the same floats two at a time).
struct ImportanceBounds {
    Vec3f center{0.0f};
    float radius2 = 0.0f;  ///< the squared radius of the box's bounding sphere
    Vec3f axis{0.0f, 0.0f, 1.0f};
    float cosThetaO = 1.0f, sinThetaO = 0.0f, cosThetaE = 0.0f;
    float intensity = 0.0f;
    bool twoSided = false;

    ImportanceBounds() = default;
    explicit ImportanceBounds(const LightBounds& b);
    float importance(const Vec3f& p, const Vec3f& n) const;
};

/// Two clusters' ImportanceBounds side by side, for the light BVH, whose walk weighs the two
/// children of a node against each other at every level of every next-event estimate.
/// importances() evaluates both at once, lane by lane with SSE where the target has it: each
/// lane does the IEEE operations of ImportanceBounds::importance in the same order (branches
/// become selections), so it gives the same two floats, bit for bit.
class ImportancePair {
  public:
    ImportancePair() = default;
    ImportancePair(const ImportanceBounds& a, const ImportanceBounds& b);
    /// {a.importance(p, n), b.importance(p, n)}.
    std::array<float, 2> importances(const Vec3f& p, const Vec3f& n) const;

  private:
    ImportanceBounds lane(std::size_t k) const;

    // Index 0: a, 1: b.
    std::array<float, 2> cx_{}, cy_{}, cz_{}, radius2_{}, ax_{}, ay_{}, az_{}, cosO_{}, sinO_{},
        cosE_{}, intensity_{};
    std::array<bool, 2> twoSided_{};
};

/// The bounds of two clusters together: the union of the boxes, the smallest cone of normals
/// holding both cones (Conty Estevez and Kulla 2018, Algorithm 1), the larger theta_e and the
/// summed intensity.
LightBounds unite(const LightBounds& a, const LightBounds& b);

/// The cone of normals' solid-angle measure M_Omega, weighted by the cosine of emission
/// (Conty Estevez and Kulla 2018, eq. 1), the orientation factor of the split cost.
float orientationMeasure(const LightBounds& b);

}  // namespace lamina::render
