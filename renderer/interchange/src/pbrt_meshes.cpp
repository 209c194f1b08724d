// pbrt-v4's polygon meshes (trianglemesh, bilinearmesh, loopsubdiv) as lamina's inline `mesh`
// (pbrt_meshes.h).
#include "pbrt_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "lamina/core/error.h"
#include "loop_subdivision.h"

namespace lamina::render::pbrt {
namespace {

// "point3 P" and "integer indices" (each within P), which every pbrt-v4 mesh shape has.
Mesh readPointsAndFaces(const Entity& e, int verticesPerFace) {
    const ParamList& params = e.params;
    Mesh mesh;
    mesh.verticesPerFace = verticesPerFace;
    const auto P = params.numbers("P", {"point3"}, 3);
    if (!P) throw InputError(e.location.str() + ": Shape \"" + e.type + "\": no \"point3 P\"");
    mesh.positions = *P;
    const std::size_t n = P->size() / 3;
    if (const auto idx = params.numbers("indices", {"integer"}, std::size_t(verticesPerFace))) {
        for (double v : *idx) {
            if (v != std::floor(v) || v < 0 || v >= double(n))
                params.fail(*params.find("indices"),
                            "has an index outside [0, " + std::to_string(n) + ")");
            mesh.indices.push_back(int(v));
        }
    } else if (n == std::size_t(verticesPerFace)) {
        // pbrt-v4 allows omitting the indices of a single triangle or patch.
        for (int i = 0; i < verticesPerFace; ++i)
            mesh.indices.push_back(i);
    } else {
        throw InputError(e.location.str() + ": Shape \"" + e.type + "\": no \"integer indices\"");
    }
    return mesh;
}

}  // namespace

Mesh readMesh(const Entity& e, int verticesPerFace) {
    const ParamList& params = e.params;
    Mesh mesh = readPointsAndFaces(e, verticesPerFace);
    const std::size_t n = mesh.positions.size() / 3;
    if (const auto N = params.numbers("N", {"normal3"}, 3)) {
        if (N->size() != mesh.positions.size())
            params.fail(*params.find("N"), "needs one normal per point");
        mesh.normals = *N;
    }
    if (const auto uv = params.numbers("uv", {"point2"}, 2)) {
        if (uv->size() / 2 != n) params.fail(*params.find("uv"), "needs one uv per point");
        mesh.uvs = *uv;
    }
    return mesh;
}

Json meshJson(const Mesh& mesh, bool reverse) {
    Json positions = Json::array(), faces = Json::array();
    for (std::size_t i = 0; i + 2 < mesh.positions.size(); i += 3)
        positions.push_back({mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]});
    const std::size_t k = std::size_t(mesh.verticesPerFace);
    for (std::size_t f = 0; f + k <= mesh.indices.size(); f += k) {
        Json face = Json::array();
        if (k == 3) {
            face = {mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]};
        } else {
            // pbrt-v4's bilinear patch orders its corners p00, p10, p01, p11; as a polygon
            // that is p00, p10, p11, p01 (the same front side: cross(p10 - p00, p01 - p00)).
            face = {mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 3], mesh.indices[f + 2]};
        }
        // ReverseOrientation turns the front side around: the reversed winding.
        if (reverse) std::reverse(face.begin(), face.end());
        faces.push_back(face);
    }
    Json shape{{"type", "mesh"}, {"positions", positions}, {"faces", faces}};
    if (!mesh.normals.empty()) {
        Json normals = Json::array();
        const double sign = reverse ? -1.0 : 1.0;
        for (std::size_t i = 0; i + 2 < mesh.normals.size(); i += 3)
            normals.push_back(
                {sign * mesh.normals[i], sign * mesh.normals[i + 1], sign * mesh.normals[i + 2]});
        shape["normals"] = normals;
    }
    if (!mesh.uvs.empty()) {
        Json uvs = Json::array();
        for (std::size_t i = 0; i + 1 < mesh.uvs.size(); i += 2)
            uvs.push_back({mesh.uvs[i], mesh.uvs[i + 1]});
        shape["uvs"] = uvs;
    }
    return shape;
}

// pbrt-v4's `loopsubdiv`: its control mesh ("point3 P", "integer indices", "integer levels" 3)
// refined by Loop subdivision to the triangles pbrt-v4 renders (loop_subdivision.h), with the
// limit normals' area-weighted stand-in (one warning).
Mesh subdividedMesh(TranslationContext& ctx, const Entity& e) {
    const ParamList& params = e.params;
    const int levels = params.integer("levels", 3);
    if (levels < 0 || levels > 12) params.fail(*params.find("levels"), "must be in [0, 12]");
    const Mesh control = readPointsAndFaces(e, 3);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i + 2 < control.positions.size(); i += 3)
        points.emplace_back(control.positions[i], control.positions[i + 1],
                            control.positions[i + 2]);
    std::vector<std::array<int, 3>> triangles;
    for (std::size_t i = 0; i + 2 < control.indices.size(); i += 3)
        triangles.push_back({control.indices[i], control.indices[i + 1], control.indices[i + 2]});
    SubdividedMesh refined;
    try {
        refined = loopSubdivide(std::move(points), std::move(triangles), levels);
    } catch (const InputError& error) {
        ctx.fail(e.location, std::string("Shape \"loopsubdiv\": ") + error.what());
    }
    if (levels > 0)
        ctx.warn(e.location,
                 "loopsubdiv: " + std::to_string(levels) +
                     " levels of Loop subdivision became a mesh of " +
                     std::to_string(refined.triangles.size()) +
                     " triangles at their limit positions, its normals averaged over the faces "
                     "(pbrt-v4 takes the limit surface's tangents; they agree as the mesh is "
                     "refined)");
    Mesh mesh;
    for (const glm::dvec3& p : refined.positions)
        mesh.positions.insert(mesh.positions.end(), {p.x, p.y, p.z});
    for (const glm::dvec3& n : refined.normals)
        mesh.normals.insert(mesh.normals.end(), {n.x, n.y, n.z});
    for (const auto& t : refined.triangles)
        mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    return mesh;
}

// The area of each face after the transform (for `power`).
std::vector<double> faceAreas(const Mesh& mesh, const glm::dmat4& m) {
    std::vector<double> areas;
    auto p = [&](int i) {
        return glm::dvec3(m * glm::dvec4(mesh.positions[std::size_t(3 * i)],
                                         mesh.positions[std::size_t(3 * i + 1)],
                                         mesh.positions[std::size_t(3 * i + 2)], 1.0));
    };
    const std::size_t k = std::size_t(mesh.verticesPerFace);
    for (std::size_t f = 0; f + k <= mesh.indices.size(); f += k) {
        const glm::dvec3 a = p(mesh.indices[f]), b = p(mesh.indices[f + 1]),
                         c = p(mesh.indices[f + 2]);
        double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        if (k == 4) {
            const glm::dvec3 d = p(mesh.indices[f + 3]);
            area += 0.5 * glm::length(glm::cross(c - d, b - d));
        }
        areas.push_back(area);
    }
    return areas;
}

bool planar(const Mesh& mesh) {
    for (std::size_t f = 0; f + 4 <= mesh.indices.size(); f += 4) {
        glm::dvec3 q[4];
        for (int i = 0; i < 4; ++i) {
            const std::size_t v = std::size_t(3 * mesh.indices[f + std::size_t(i)]);
            q[i] = {mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2]};
        }
        const glm::dvec3 n = glm::cross(q[1] - q[0], q[2] - q[0]);
        const double size = glm::length(q[1] - q[0]) + glm::length(q[2] - q[0]);
        if (std::abs(glm::dot(n, q[3] - q[0])) > 1e-9 * size * size * size) return false;
    }
    return true;
}

}  // namespace lamina::render::pbrt
