#include <tiny_obj_loader.h>

#include <map>

#include "lamina/core/error.h"
#include "lamina/render/mesh_files.h"

namespace lamina::render {

// Vertices are shared between triangles where the OBJ shares the same position, normal and
// uv indices; normals and uvs are kept only when every face vertex has one.
void readObj(const std::filesystem::path& file, MeshDesc& mesh) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config))
        throw InputError(file.string() + ": " +
                         (reader.Error().empty() ? "cannot read the OBJ file" : reader.Error()));
    const auto& attrib = reader.GetAttrib();
    std::map<std::array<int, 3>, std::uint32_t> unique;
    bool hasNormals = !attrib.normals.empty(), hasUvs = !attrib.texcoords.empty();
    for (const auto& shape : reader.GetShapes())
        for (const auto& index : shape.mesh.indices) {
            hasNormals &= index.normal_index >= 0;
            hasUvs &= index.texcoord_index >= 0;
        }
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
            std::array<std::uint32_t, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                const auto& i = idx[t + std::size_t(k)];
                const std::array<int, 3> key{i.vertex_index, hasNormals ? i.normal_index : -1,
                                             hasUvs ? i.texcoord_index : -1};
                auto [it, inserted] = unique.emplace(key, std::uint32_t(mesh.positions.size()));
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
    if (mesh.triangles.empty()) throw InputError(file.string() + ": no triangles");
}

}  // namespace lamina::render
