// A reader for PLY triangle meshes (Turk 1994, "The PLY Polygon File Format"): ASCII and
// binary little- and big-endian, vertex positions (x, y, z) with optional normals
// (nx, ny, nz) and texture coordinates (u, v or s, t), polygonal faces (split as fans).
// Properties of other elements and unknown vertex properties are skipped.
#pragma once

#include <filesystem>

#include "lamina/render/scene_description.h"

namespace lamina::render {

/// Appends the file's geometry to `mesh` (positions, normals, uvs, triangles). Errors are
/// InputErrors naming the file and what was wrong.
void readPly(const std::filesystem::path& file, MeshDesc& mesh);

}  // namespace lamina::render
