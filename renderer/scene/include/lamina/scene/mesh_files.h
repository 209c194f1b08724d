// Triangle meshes from files. The readers append the file's geometry to a MeshDesc
// (positions, optional normals and uvs, triangles; polygons split as fans) and throw
// InputErrors that name the file and what was wrong.
//   obj_reader.cpp  Wavefront OBJ, through tinyobjloader
//   ply_reader.cpp  PLY (Turk 1994, "The PLY Polygon File Format"): ASCII and binary little-
//                   and big-endian, vertex positions (x, y, z) with optional normals (nx, ny,
//                   nz) and texture coordinates (u, v or s, t), polygonal faces. Properties of
//                   other elements and unknown vertex properties are skipped.
//   serialized_reader.cpp  Mitsuba's serialized meshes (versions 3 and 4): zlib-compressed
//                   positions, optional normals and uvs, triangles; one mesh of a file of several.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "lamina/scene/scene_description.h"

namespace lamina::render {

void readObj(const std::filesystem::path& file, MeshDesc& mesh);
void readPly(const std::filesystem::path& file, MeshDesc& mesh);
/// Mesh `shapeIndex` (0 the first) of a Mitsuba serialized file.
void readSerialized(const std::filesystem::path& file, std::uint32_t shapeIndex, MeshDesc& mesh);

/// The first vertex from `first` on whose position, normal or uv is NaN or infinite (in
/// float: 1e39 overflows), or whose normal is zero, described as "vertex 7: normal (0, 0,
/// 0) is zero" (numbered from `first`); nothing when every vertex is usable.
std::optional<std::string> firstBadVertex(const MeshDesc& mesh, std::size_t first);

}  // namespace lamina::render
