// pbrt-v4's polygon meshes -> lamina's inline `mesh` shape (pbrt_meshes.cpp): reading
// trianglemesh and bilinearmesh parameters, refining loopsubdiv, and the mesh's face areas for
// pbrt's area-light `power`.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "pbrt_translation.h"

namespace lamina::render::pbrt {

/// A pbrt mesh: flat coordinate lists and face indices of `verticesPerFace` (3 or 4) corners.
struct Mesh {
    std::vector<double> positions, normals, uvs;
    std::vector<int> indices;
    int verticesPerFace = 3;
};

/// "point3 P", "integer indices", "normal N", "point2 uv" of a trianglemesh or bilinearmesh.
Mesh readMesh(const Entity& e, int verticesPerFace);
/// The lamina `mesh` shape; `reverse`: ReverseOrientation (winding and normals turned).
Json meshJson(const Mesh& mesh, bool reverse);
/// pbrt-v4's `loopsubdiv` refined to the mesh pbrt-v4 renders (loop_subdivision.h).
Mesh subdividedMesh(TranslationContext& ctx, const Entity& e);
/// Each face's area after the transform `m`.
std::vector<double> faceAreas(const Mesh& mesh, const glm::dmat4& m);
/// Whether every quad of a bilinear mesh is planar.
bool planar(const Mesh& mesh);

}  // namespace lamina::render::pbrt
