#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/scene/mesh_files.h"
#include "lamina/scene/obj_materials.h"

namespace lamina::render {

namespace {

// tinyobjloader skips what it cannot use (degenerate faces, faces with invalid indices,
// unparsable lines) and says so only in its warnings: those are errors of the mesh. The
// warnings about materials are not: readObjGroups reports those itself, with their lines.
void refuseGeometryWarnings(const std::filesystem::path& file, const std::string& warnings) {
    std::istringstream lines(warnings);
    for (std::string line; std::getline(lines, line);) {
        if (line.find_first_not_of(" \t\r.") == std::string::npos) continue;
        if (line.find("aterial") != std::string::npos || line.find("mtl") != std::string::npos ||
            line.find("group name") != std::string::npos)
            continue;
        // tinyobjloader's "out of bounds (line N.)" gives the file's last line, not the
        // face's: drop it.
        if (const auto at = line.find(" (line ");
            at != std::string::npos && line.find("out of bounds") != std::string::npos)
            line = line.substr(0, at);
        throw InputError(file.string() + ": " + line);
    }
}

// Checks one index of a face corner against its array: `optional` arrays (normals, uvs)
// may be absent at a corner (index -1).
void checkIndex(const std::filesystem::path& file, const std::string& face, const char* what,
                int index, std::size_t count, bool optional) {
    if ((optional && index == -1) || (index >= 0 && std::size_t(index) < count)) return;
    throw InputError(file.string() + ": " + face + ": " + what + " index " +
                     std::to_string(index >= 0 ? std::int64_t(index) + 1 : std::int64_t(index)) +
                     " is out of range (the file has " + std::to_string(count) + ")");
}

// The first NaN or infinite number of an attribute array (v, vn or vt lines, `n` numbers
// each; 1e39 overflows to infinity in float), or a zero normal: geometry that would silently
// disappear or shade as NaN.
void checkValues(const std::filesystem::path& file, const std::vector<tinyobj::real_t>& values,
                 std::size_t n, const char* what, bool normal) {
    for (std::size_t i = 0; i + n <= values.size(); i += n) {
        bool finite = true, zero = true;
        for (std::size_t c = 0; c < n; ++c) {
            finite &= std::isfinite(values[i + c]);
            zero &= values[i + c] == 0;
        }
        if (!finite || (normal && zero))
            throw InputError(file.string() + ": " + what + " " + std::to_string(i / n + 1) +
                             (finite ? " is zero" : " is not finite (in single precision)"));
    }
}

// tinyobjloader reads a number it cannot parse ("nan", "inf", "x") as 0, so a vertex of NaN
// or infinity would become a vertex at the origin. The numbers of the v, vn and vt lines are
// read here first: each must be a finite number (the PLY reader refuses the same).
void checkAttributeNumbers(const std::filesystem::path& file, const std::string& text) {
    std::istringstream in(text);
    std::size_t lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        std::istringstream tokens(line);
        std::string keyword;
        tokens >> keyword;
        const char* what = keyword == "v"    ? "vertex position (v)"
                           : keyword == "vn" ? "normal (vn)"
                           : keyword == "vt" ? "texture coordinate (vt)"
                                             : nullptr;
        if (!what) continue;
        for (std::string token; tokens >> token;) {
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            const bool number = end == token.c_str() + token.size();
            if (number && std::isfinite(v)) continue;
            throw InputError(file.string() + ": line " + std::to_string(lineNumber) + ": " + what +
                             ": \"" + token.substr(0, 40) + "\" is " +
                             (number ? "not a finite number" : "not a number"));
        }
    }
}

tinyobj::ObjReader parseObj(const std::filesystem::path& file, const std::string& text,
                            const std::string& mtlText) {
    checkAttributeNumbers(file, text);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, mtlText, config))
        throw InputError(file.string() + ": " +
                         (reader.Error().empty() ? "cannot read the OBJ file" : reader.Error()));
    return reader;
}

// Builds the triangles of every face into one mesh per key `keyOf(shape, triangle)`, in the
// order the keys first appear. Vertices are shared within a mesh where the OBJ shares the
// same position, normal and uv indices; normals and uvs are kept only when every face vertex
// of the file has one.
template <typename KeyOf>
std::vector<std::pair<int, MeshDesc>> buildMeshes(const std::filesystem::path& file,
                                                  const tinyobj::ObjReader& reader, KeyOf keyOf) {
    std::vector<std::pair<int, MeshDesc>> meshes;
    std::map<int, std::size_t> meshOfKey;
    const auto& attrib = reader.GetAttrib();
    checkValues(file, attrib.vertices, 3, "vertex position (v)", false);
    checkValues(file, attrib.normals, 3, "normal (vn)", true);
    checkValues(file, attrib.texcoords, 2, "texture coordinate (vt)", false);
    const std::size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3,
                      uvs = attrib.texcoords.size() / 2;
    std::map<int, std::map<std::array<int, 3>, std::uint32_t>> unique;  // per key
    bool hasNormals = normals > 0, hasUvs = uvs > 0;
    for (const auto& shape : reader.GetShapes())
        for (const auto& index : shape.mesh.indices) {
            hasNormals &= index.normal_index >= 0;
            hasUvs &= index.texcoord_index >= 0;
        }
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
            const std::string face =
                (shape.name.empty() ? std::string() : "object \"" + shape.name + "\", ") +
                "triangle " + std::to_string(t / 3);
            const int meshKey = keyOf(shape, t / 3);
            const auto [at, added] = meshOfKey.emplace(meshKey, meshes.size());
            if (added) meshes.emplace_back(meshKey, MeshDesc{});
            MeshDesc& mesh = meshes[at->second].second;
            auto& shared = unique[meshKey];
            std::array<std::uint32_t, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                const auto& i = idx[t + std::size_t(k)];
                // OBJ indices in messages count from 1, as in the file.
                checkIndex(file, face, "vertex", i.vertex_index, positions, false);
                checkIndex(file, face, "normal", i.normal_index, normals, true);
                checkIndex(file, face, "texture coordinate", i.texcoord_index, uvs, true);
                const std::array<int, 3> key{i.vertex_index, hasNormals ? i.normal_index : -1,
                                             hasUvs ? i.texcoord_index : -1};
                auto [it, inserted] = shared.emplace(key, std::uint32_t(mesh.positions.size()));
                if (inserted) {
                    const auto v = std::size_t(i.vertex_index) * 3;
                    mesh.positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1],
                                                attrib.vertices[v + 2]);
                    if (hasNormals) {
                        const auto n = std::size_t(i.normal_index) * 3;
                        mesh.normals.emplace_back(attrib.normals[n], attrib.normals[n + 1],
                                                  attrib.normals[n + 2]);
                    }
                    if (hasUvs) {
                        const auto u = std::size_t(i.texcoord_index) * 2;
                        mesh.uvs.emplace_back(attrib.texcoords[u], attrib.texcoords[u + 1]);
                    }
                }
                tri[std::size_t(k)] = it->second;
            }
            mesh.triangles.push_back(tri);
        }
    }
    // After the faces' own checks, which name the face: what is left are the faces
    // tinyobjloader dropped.
    refuseGeometryWarnings(file, reader.Warning());
    return meshes;
}

// The OBJ's `mtllib` files (several per line allowed) and the first line of each `usemtl`
// name, scanned from the text (tinyobjloader reports neither with its line).
struct MaterialLines {
    std::vector<std::pair<std::string, int>> libraries;
    std::map<std::string, int> used;
};

MaterialLines scanMaterialLines(const std::string& text) {
    MaterialLines out;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "mtllib") {
            for (std::string name; words >> name;)
                out.libraries.emplace_back(name, number);
        } else if (key == "usemtl") {
            std::string name;
            words >> name;
            out.used.emplace(name, number);
        }
    }
    return out;
}

}  // namespace

void readObj(const std::filesystem::path& file, MeshDesc& mesh) {
    const tinyobj::ObjReader reader = parseObj(file, readInputFile(file, kMaxMeshFileBytes), "");
    auto meshes = buildMeshes(file, reader, [](const tinyobj::shape_t&, std::size_t) { return 0; });
    if (meshes.empty()) throw InputError(file.string() + ": no triangles");
    MeshDesc& built = meshes.front().second;
    mesh.positions = std::move(built.positions);
    mesh.normals = std::move(built.normals);
    mesh.uvs = std::move(built.uvs);
    mesh.triangles = std::move(built.triangles);
}

ObjGroups readObjGroups(const std::filesystem::path& file) {
    const std::string text = readInputFile(file, kMaxMeshFileBytes);
    const MaterialLines lines = scanMaterialLines(text);
    if (lines.libraries.empty())
        throw InputError(file.string() +
                         ": names no MTL library (mtllib); give the shape a material");
    ObjGroups out;
    std::map<std::string, std::size_t> byName;  // newmtl name -> index in out.materials
    std::string mtlText;
    for (const auto& [name, line] : lines.libraries) {
        const std::filesystem::path library = (file.parent_path() / name).lexically_normal();
        if (std::find(out.libraries.begin(), out.libraries.end(), library) != out.libraries.end())
            continue;  // named twice
        if (const std::string why = notARegularFile(library); !why.empty())
            throw InputError(file.string() + ":" + std::to_string(line) + ": mtllib " + name +
                             ": " + library.string() + ": " + why);
        const std::string libraryText = readInputFile(library, kMaxMeshFileBytes);
        for (MtlMaterial& m : readMtlLibrary(library, libraryText, out.warnings)) {
            const auto [at, added] = byName.emplace(m.mtlName, out.materials.size());
            if (!added) {
                const MtlMaterial& other = out.materials[at->second];
                throw InputError(library.string() + ":" + std::to_string(m.line) + ": newmtl " +
                                 m.mtlName + " is also defined in " + other.file.string() + ":" +
                                 std::to_string(other.line));
            }
            out.materials.push_back(std::move(m));
        }
        out.libraries.push_back(library);
        mtlText += libraryText + "\n";
    }
    const tinyobj::ObjReader reader = parseObj(file, text, mtlText);
    // tinyobjloader's material ids -> ours, by name.
    const auto& parsed = reader.GetMaterials();
    std::vector<int> ours(parsed.size(), -1);
    for (std::size_t i = 0; i < parsed.size(); ++i)
        if (const auto at = byName.find(parsed[i].name); at != byName.end())
            ours[i] = int(at->second);
    for (const auto& [name, line] : lines.used)
        if (!byName.count(name))
            out.warnings.push_back(file.string() + ":" + std::to_string(line) + ": usemtl " + name +
                                   ": no such material in the MTL libraries");
    std::size_t unassigned = 0;
    auto meshes = buildMeshes(file, reader, [&](const tinyobj::shape_t& shape, std::size_t face) {
        const int id = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
        const int material = id >= 0 && std::size_t(id) < ours.size() ? ours[std::size_t(id)] : -1;
        if (material < 0) ++unassigned;
        return material;
    });
    for (auto& [material, mesh] : meshes)
        out.groups.push_back({material, std::move(mesh)});
    if (out.groups.empty()) throw InputError(file.string() + ": no triangles");
    if (unassigned > 0)
        out.warnings.push_back(file.string() + ": " + std::to_string(unassigned) +
                               " triangles have no material (no usemtl before them, or an "
                               "unknown one): a default lambert 0.5");
    return out;
}

}  // namespace lamina::render
