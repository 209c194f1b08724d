// A bounding volume hierarchy over the lights with a position (area, point and spot lights)
// that picks one in proportion to an estimate of what it sends to a shading point (Conty
// Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree Splitting",
// without the splitting: one light per query, as pbrt-v4's BVHLightSampler). Each node holds
// the LightBounds of its lights; a query walks from the root and at every node takes a child
// with probability proportional to the child's importance at the point. probability() walks
// the same nodes with the same arithmetic, so it is exactly the chance that choose() returns
// a light, which multiple importance sampling relies on.
#pragma once

#include <cstddef>
#include <vector>

#include "lamina/lights/light_bounds.h"

namespace lamina::render {

/// A light picked for a shading point: its index in the LightSet and the probability.
struct LightChoice {
    std::size_t index;
    float probability;
};

class LightBvh {
  public:
    struct Entry {
        std::size_t light;  ///< index in the LightSet
        LightBounds bounds;
    };

    LightBvh() = default;
    /// Builds the tree by binned splits that minimise Conty Estevez and Kulla's cost (their
    /// eq. 2: intensity times orientation measure times box surface area, summed over the two
    /// children, regularised against thin boxes).
    explicit LightBvh(std::vector<Entry> lights);

    bool empty() const { return nodes_.empty(); }
    /// Picks a light for point `p` with surface normal `n` (the zero vector: none); the tree
    /// must not be empty. A light that cannot send light to p has probability 0 unless its
    /// cluster's bounds could and none of the cluster's parts can (then the parts are taken
    /// half and half), so the probabilities always sum to 1. (Not an optional: a LightChoice
    /// comes back in registers, and this runs at every next-event estimate.)
    LightChoice choose(const Vec3f& p, const Vec3f& n, float u) const;
    /// The probability that choose(p, n, u) returns `light` for a uniform u (0 for a light
    /// that is not in the tree).
    float probability(std::size_t light, const Vec3f& p, const Vec3f& n) const;
    /// Whether LightSet light `light` is a leaf of the tree.
    bool contains(std::size_t light) const { return light < leafOf_.size() && leafOf_[light] >= 0; }
    /// The number of levels below the root of the deepest leaf.
    int depth() const { return depth_; }

  private:
    struct Node {
        ImportancePair children;    ///< the bounds of the left and the right child
        int left = -1, right = -1;  ///< children; -1 for a leaf
        int parent = -1;
        std::size_t light = 0;  ///< a leaf's light
        bool leaf() const { return left < 0; }
    };

    /// Builds the subtree of lights [begin, end) at `depth` under `parent` (its root is the
    /// next node); returns the subtree's bounds.
    LightBounds build(std::vector<Entry>& lights, std::size_t begin, std::size_t end, int parent,
                      int depth);
    /// The probability of taking the left child of interior node `node` at (p, n), in
    /// proportion to the children's importance (1/2 when both are 0).
    float leftProbability(const Node& node, const Vec3f& p, const Vec3f& n) const;

    /// Past this depth the build splits at the median (at most 32 more levels), so that a
    /// path from a leaf to the root always fits kMaxDepth.
    static constexpr int kMedianSplitDepth = 64;
    static constexpr int kMaxDepth = kMedianSplitDepth + 33;

    std::vector<Node> nodes_;  ///< the root first
    std::vector<int> leafOf_;  ///< per LightSet index: its leaf, or -1
    int depth_ = 0;
};

}  // namespace lamina::render
