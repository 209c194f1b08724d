#include <cmath>
#include <sstream>

#include "lamina/scene/mesh_files.h"

namespace lamina::render {

namespace {

template <typename V>
std::string components(const V& v, int n) {
    std::ostringstream s;
    s << "(";
    for (int c = 0; c < n; ++c)
        s << (c ? ", " : "") << v[c];
    s << ")";
    return s.str();
}

template <typename V>
bool finite(const V& v, int n) {
    for (int c = 0; c < n; ++c)
        if (!std::isfinite(v[c])) return false;
    return true;
}

}  // namespace

// A NaN position makes Embree drop the triangle and a zero normal makes the shading frame
// NaN: both would make geometry silently disappear, so they are input errors.
std::optional<std::string> firstBadVertex(const MeshDesc& mesh, std::size_t first) {
    for (std::size_t i = first; i < mesh.positions.size(); ++i) {
        // Made only for the vertex that fails: a mesh file has millions.
        const auto vertex = [&] { return "vertex " + std::to_string(i - first) + ": "; };
        if (!finite(mesh.positions[i], 3))
            return vertex() + "position " + components(mesh.positions[i], 3) +
                   " is not finite (in single precision)";
        if (i < mesh.normals.size()) {
            const Vec3<float>& n = mesh.normals[i];
            if (!finite(n, 3))
                return vertex() + "normal " + components(n, 3) +
                       " is not finite (in single precision)";
            if (n.x == 0 && n.y == 0 && n.z == 0)
                return vertex() + "normal " + components(n, 3) + " is zero";
        }
        if (i < mesh.uvs.size() && !finite(mesh.uvs[i], 2))
            return vertex() + "uv " + components(mesh.uvs[i], 2) + " is not finite";
    }
    return std::nullopt;
}

}  // namespace lamina::render
