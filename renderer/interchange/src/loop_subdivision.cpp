#include "loop_subdivision.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "lamina/core/error.h"

namespace lamina::render::pbrt {

namespace {

struct Edge {
    int a, b;
    int opposite[2] = {-1, -1};
    int faces = 0;
};

// The edges of a triangle mesh, each once, with the corners opposite it.
struct EdgeTable {
    std::vector<Edge> edges;
    std::vector<std::array<int, 3>> ofTriangle;  ///< edge k runs from corner k to corner k + 1

    explicit EdgeTable(const std::vector<std::array<int, 3>>& triangles) {
        std::unordered_map<std::uint64_t, int> index;
        index.reserve(triangles.size() * 2);
        ofTriangle.resize(triangles.size());
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const auto& tri = triangles[t];
            for (int k = 0; k < 3; ++k) {
                const int a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
                const int c = tri[std::size_t((k + 2) % 3)];
                const std::uint64_t key = (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) |
                                          std::uint32_t(std::max(a, b));
                const auto [it, added] = index.emplace(key, int(edges.size()));
                if (added) edges.push_back({std::min(a, b), std::max(a, b)});
                Edge& e = edges[std::size_t(it->second)];
                if (e.faces == 2)
                    throw InputError("the edge between points " + std::to_string(e.a) + " and " +
                                     std::to_string(e.b) +
                                     " belongs to more than two triangles (Loop subdivision "
                                     "needs each edge in one or two)");
                e.opposite[e.faces++] = c;
                ofTriangle[t][std::size_t(k)] = it->second;
            }
        }
    }
};

// What the vertex rules need of each vertex's neighbourhood.
struct Neighbourhoods {
    std::vector<int> valence, boundaryEdges;
    std::vector<glm::dvec3> ringSum, boundarySum;

    Neighbourhoods(const std::vector<glm::dvec3>& p, const EdgeTable& table)
        : valence(p.size(), 0),
          boundaryEdges(p.size(), 0),
          ringSum(p.size(), glm::dvec3(0.0)),
          boundarySum(p.size(), glm::dvec3(0.0)) {
        for (const Edge& e : table.edges) {
            const auto a = std::size_t(e.a), b = std::size_t(e.b);
            ++valence[a];
            ++valence[b];
            ringSum[a] += p[b];
            ringSum[b] += p[a];
            if (e.faces == 1) {
                ++boundaryEdges[a];
                ++boundaryEdges[b];
                boundarySum[a] += p[b];
                boundarySum[b] += p[a];
            }
        }
    }
};

// Warren's vertex weight (file comment).
double beta(int valence) {
    return valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * valence);
}

// An old vertex's position after one round (limit = false) or at the limit (limit = true).
glm::dvec3 vertexRule(const std::vector<glm::dvec3>& p, const Neighbourhoods& n, std::size_t i,
                      bool limit) {
    const int boundary = n.boundaryEdges[i];
    if (boundary == 2)
        return limit ? 0.6 * p[i] + 0.2 * n.boundarySum[i] : 0.75 * p[i] + 0.125 * n.boundarySum[i];
    const int valence = n.valence[i];
    if (boundary != 0 || valence == 0) return p[i];
    const double b = beta(valence);
    const double w = limit ? 1.0 / (valence + 3.0 / (8.0 * b)) : b;
    return (1.0 - valence * w) * p[i] + w * n.ringSum[i];
}

}  // namespace

SubdividedMesh loopSubdivide(std::vector<glm::dvec3> positions,
                             std::vector<std::array<int, 3>> triangles, int levels) {
    for (const auto& t : triangles)
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            throw InputError("a triangle repeats point " +
                             std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) +
                             " (Loop subdivision needs three distinct corners)");
    // The count first, before any work or memory (4^levels x the triangles).
    std::size_t count = triangles.size();
    for (int level = 0; level < levels; ++level) {
        if (count > kMaxSubdividedTriangles / 4)
            throw InputError(std::to_string(levels) + " levels make more than " +
                             std::to_string(kMaxSubdividedTriangles) +
                             " triangles of this mesh: use fewer");
        count *= 4;
    }
    for (int level = 0; level < levels; ++level) {
        const EdgeTable table(triangles);
        const Neighbourhoods n(positions, table);
        std::vector<glm::dvec3> next(positions.size() + table.edges.size());
        for (std::size_t i = 0; i < positions.size(); ++i)
            next[i] = vertexRule(positions, n, i, false);
        for (std::size_t e = 0; e < table.edges.size(); ++e) {
            const Edge& edge = table.edges[e];
            const glm::dvec3 a = positions[std::size_t(edge.a)], b = positions[std::size_t(edge.b)];
            next[positions.size() + e] =
                edge.faces == 2
                    ? 0.375 * (a + b) + 0.125 * (positions[std::size_t(edge.opposite[0])] +
                                                 positions[std::size_t(edge.opposite[1])])
                    : 0.5 * (a + b);
        }
        std::vector<std::array<int, 3>> refined;
        refined.reserve(triangles.size() * 4);
        const int first = int(positions.size());
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const auto& v = triangles[t];
            const auto& e = table.ofTriangle[t];
            // Edge k runs from corner k to k + 1: corner k sits between edges k - 1 and k.
            const int e0 = first + e[0], e1 = first + e[1], e2 = first + e[2];
            refined.push_back({v[0], e0, e2});
            refined.push_back({v[1], e1, e0});
            refined.push_back({v[2], e2, e1});
            refined.push_back({e0, e1, e2});
        }
        positions = std::move(next);
        triangles = std::move(refined);
    }
    SubdividedMesh out;
    {
        const EdgeTable table(triangles);
        const Neighbourhoods n(positions, table);
        out.positions.resize(positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i)
            out.positions[i] = vertexRule(positions, n, i, true);
    }
    out.normals.assign(out.positions.size(), glm::dvec3(0.0));
    for (const auto& t : triangles) {
        const glm::dvec3 p0 = out.positions[std::size_t(t[0])];
        // Twice the area times the unit normal: the area weighting.
        const glm::dvec3 n = glm::cross(out.positions[std::size_t(t[1])] - p0,
                                        out.positions[std::size_t(t[2])] - p0);
        for (const int v : t)
            out.normals[std::size_t(v)] += n;
    }
    for (glm::dvec3& n : out.normals) {
        const double length = glm::length(n);
        // A vertex no triangle uses, or whose faces cancel, has no normal: no shading normals.
        if (!(length > 0.0) || !std::isfinite(length)) {
            out.normals.clear();
            break;
        }
        n /= length;
    }
    out.triangles = std::move(triangles);
    return out;
}

}  // namespace lamina::render::pbrt
