#include "lamina/lights/light_bvh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

namespace lamina::render {

namespace {

constexpr int kBuckets = 12;

/// The box's surface area, with a little of its squared diagonal so that boxes flattened to
/// a line or a point (lights in a row, lights at one place) still compare by size.
float boxMeasure(const LightBounds& b) {
    const Vec3f e = b.upper - b.lower;
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x) + 1e-3f * lengthSquared(e);
}

/// Conty Estevez and Kulla 2018, eq. 2, for one child (the parent's normalisation is the same
/// for every candidate split of a node and left out).
float clusterCost(const LightBounds& b) {
    return b.intensity * orientationMeasure(b) * boxMeasure(b);
}

int bucketOf(float c, float lo, float hi) {
    return std::clamp(int(float(kBuckets) * (c - lo) / (hi - lo)), 0, kBuckets - 1);
}

}  // namespace

LightBvh::LightBvh(std::vector<Entry> lights) {
    if (lights.empty()) return;
    std::size_t last = 0;
    for (const Entry& e : lights)
        last = std::max(last, e.light);
    leafOf_.assign(last + 1, -1);
    nodes_.reserve(2 * lights.size() - 1);
    build(lights, 0, lights.size(), -1, 0);
}

LightBounds LightBvh::build(std::vector<Entry>& lights, std::size_t begin, std::size_t end,
                            int parent, int depth) {
    const int index = int(nodes_.size());
    nodes_.emplace_back();
    nodes_[std::size_t(index)].parent = parent;
    depth_ = std::max(depth_, depth);
    if (end - begin == 1) {
        Node& leaf = nodes_[std::size_t(index)];
        leaf.light = lights[begin].light;
        leafOf_[leaf.light] = index;
        return lights[begin].bounds;
    }

    LightBounds all = lights[begin].bounds;
    Vec3f centerLo = all.center(), centerHi = all.center();
    for (std::size_t i = begin + 1; i < end; ++i) {
        all = unite(all, lights[i].bounds);
        centerLo = glm::min(centerLo, lights[i].bounds.center());
        centerHi = glm::max(centerHi, lights[i].bounds.center());
    }

    // The cheapest split between buckets of centroids along one axis.
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1, bestSplit = 0;
    const Vec3f extent = all.upper - all.lower;
    const float maxExtent = std::max({extent.x, extent.y, extent.z});
    for (int axis = 0; axis < 3 && depth < kMedianSplitDepth; ++axis) {
        const float lo = centerLo[axis], hi = centerHi[axis];
        if (!(hi > lo)) continue;
        std::array<std::optional<LightBounds>, kBuckets> buckets;
        for (std::size_t i = begin; i < end; ++i) {
            const LightBounds& b = lights[i].bounds;
            auto& bucket = buckets[std::size_t(bucketOf(b.center()[axis], lo, hi))];
            bucket = bucket ? unite(*bucket, b) : b;
        }
        std::array<std::optional<LightBounds>, kBuckets> above;  // buckets [k, kBuckets)
        for (int k = kBuckets - 1; k >= 0; --k) {
            const auto& next = k + 1 < kBuckets ? above[std::size_t(k + 1)] : std::nullopt;
            const auto& here = buckets[std::size_t(k)];
            above[std::size_t(k)] = here && next ? unite(*here, *next) : (here ? here : next);
        }
        // Thin boxes split across their thin side are penalised (pbrt-v4's regulariser).
        const float regulariser = maxExtent / extent[axis];
        std::optional<LightBounds> below;  // buckets [0, k)
        for (int k = 1; k < kBuckets; ++k) {
            const auto& here = buckets[std::size_t(k - 1)];
            if (here) below = below ? unite(*below, *here) : *here;
            if (!below || !above[std::size_t(k)]) continue;
            const float cost =
                regulariser * (clusterCost(*below) + clusterCost(*above[std::size_t(k)]));
            if (cost < bestCost) {
                bestCost = cost;
                bestAxis = axis;
                bestSplit = k;
            }
        }
    }

    std::size_t mid;
    if (bestAxis >= 0) {
        const float lo = centerLo[bestAxis], hi = centerHi[bestAxis];
        const auto it =
            std::partition(lights.begin() + std::ptrdiff_t(begin),
                           lights.begin() + std::ptrdiff_t(end), [&](const Entry& e) {
                               return bucketOf(e.bounds.center()[bestAxis], lo, hi) < bestSplit;
                           });
        mid = std::size_t(it - lights.begin());
    } else {
        // Centroids all at one place, or deep in the tree: halves by count along the widest
        // spread of centroids.
        const Vec3f spread = centerHi - centerLo;
        const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                         : spread.y >= spread.z                       ? 1
                                                                      : 2;
        mid = begin + (end - begin) / 2;
        std::nth_element(lights.begin() + std::ptrdiff_t(begin),
                         lights.begin() + std::ptrdiff_t(mid), lights.begin() + std::ptrdiff_t(end),
                         [axis](const Entry& a, const Entry& b) {
                             return a.bounds.center()[axis] < b.bounds.center()[axis];
                         });
    }
    const int left = int(nodes_.size());
    const LightBounds leftBounds = build(lights, begin, mid, index, depth + 1);
    const int right = int(nodes_.size());
    const LightBounds rightBounds = build(lights, mid, end, index, depth + 1);
    Node& node = nodes_[std::size_t(index)];
    node.children = ImportancePair(ImportanceBounds(leftBounds), ImportanceBounds(rightBounds));
    node.left = left;
    node.right = right;
    return all;
}

float LightBvh::leftProbability(const Node& node, const Vec3f& p, const Vec3f& n) const {
    const auto [left, right] = node.children.importances(p, n);
    const double l = left, r = right;
    // Neither child can send light to p although the node's looser bounds allowed it: halves,
    // so that the probabilities still sum to 1 (the lights reached contribute nothing).
    if (!(l + r > 0.0)) return 0.5f;
    return float(l / (l + r));
}

LightChoice LightBvh::choose(const Vec3f& p, const Vec3f& n, float u) const {
    const Node* node = &nodes_.front();
    float probability = 1.0f;
    while (!node->leaf()) {
        const float pLeft = leftProbability(*node, p, n);
        const bool left = u < pLeft;
        probability *= left ? pLeft : 1.0f - pLeft;
        node = &nodes_[std::size_t(left ? node->left : node->right)];
        // u is reused below: rescaled to [0, 1) within the part of it that chose the child.
        // A leaf uses no more of it (and the two-light tree of a quad lamp then divides not
        // at all).
        if (node->leaf()) break;
        u = left ? std::min(u / pLeft, kOneMinusEpsilon<float>)
                 : std::min((u - pLeft) / (1.0f - pLeft), kOneMinusEpsilon<float>);
    }
    return LightChoice{node->light, probability};
}

float LightBvh::probability(std::size_t light, const Vec3f& p, const Vec3f& n) const {
    if (!contains(light)) return 0.0f;
    // The nodes from the leaf up to the root, then the same products as choose() top down.
    std::array<int, kMaxDepth + 1> trail;
    int length = 0;
    for (int i = leafOf_[light]; i >= 0; i = nodes_[std::size_t(i)].parent)
        trail[std::size_t(length++)] = i;
    float probability = 1.0f;
    for (int k = length - 1; k >= 1; --k) {
        const Node& node = nodes_[std::size_t(trail[std::size_t(k)])];
        const float pLeft = leftProbability(node, p, n);
        probability *= trail[std::size_t(k - 1)] == node.left ? pLeft : 1.0f - pLeft;
    }
    return probability;
}

}  // namespace lamina::render
