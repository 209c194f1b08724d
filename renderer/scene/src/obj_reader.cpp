#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>

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
// may be absent at a corner (index -1). `face()` names the face, made only for a message.
template <typename FaceName>
void checkIndex(const std::filesystem::path& file, const FaceName& face, const char* what,
                int index, std::size_t count, bool optional) {
    if ((optional && index == -1) || (index >= 0 && std::size_t(index) < count)) return;
    throw InputError(file.string() + ": " + face() + ": " + what + " index " +
                     std::to_string(index >= 0 ? std::int64_t(index) + 1 : std::int64_t(index)) +
                     " is out of range (the file has " + std::to_string(count) + ")");
}

// A face corner's (position, normal, uv) indices, the key under which a mesh shares one
// vertex.
struct CornerKey {
    int position, normal, uv;
    bool operator==(const CornerKey&) const = default;
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        std::uint64_t h = std::uint32_t(k.position);
        h = h * 0x9E3779B97F4A7C15ull ^ std::uint32_t(k.normal);
        h = h * 0x9E3779B97F4A7C15ull ^ std::uint32_t(k.uv);
        return std::size_t(h ^ (h >> 29));
    }
};

// The mesh vertex of each corner key seen so far. A position's first key is kept in an array
// indexed by the position (one look-up, no hashing: most files give a position one normal and
// one uv); a position met again with another normal or uv goes to a hash map.
class SharedCorners {
  public:
    explicit SharedCorners(std::size_t positions) : first_(positions) {}

    /// The vertex of `key`, or a new one numbered `next` (`added` says which).
    std::uint32_t vertexOf(const CornerKey& key, std::uint32_t next, bool& added) {
        First& f = first_[std::size_t(key.position)];
        added = false;
        if (f.vertex == kNone) {
            f = {next, key.normal, key.uv};
            added = true;
            return next;
        }
        if (f.normal == key.normal && f.uv == key.uv) return f.vertex;
        const auto [it, inserted] = others_.emplace(key, next);
        added = inserted;
        return it->second;
    }

  private:
    static constexpr std::uint32_t kNone = 0xffffffffu;
    struct First {
        std::uint32_t vertex = kNone;
        int normal = -1, uv = -1;
    };
    std::vector<First> first_;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> others_;
};

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
    // A scan over the text with pointers: a stream per line took most of a big file's time.
    const char* at = text.data();
    const char* const end = text.data() + text.size();
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    for (std::size_t lineNumber = 1; at < end; ++lineNumber) {
        const char* lineEnd =
            static_cast<const char*>(std::memchr(at, '\n', std::size_t(end - at)));
        if (!lineEnd) lineEnd = end;
        const char* p = at;
        at = lineEnd + 1;
        while (p < lineEnd && blank(*p))
            ++p;
        const char* keyword = p;
        while (p < lineEnd && !blank(*p))
            ++p;
        const std::string_view k(keyword, std::size_t(p - keyword));
        const char* what = k == "v"    ? "vertex position (v)"
                           : k == "vn" ? "normal (vn)"
                           : k == "vt" ? "texture coordinate (vt)"
                                       : nullptr;
        if (!what) continue;
        for (;;) {
            while (p < lineEnd && blank(*p))
                ++p;
            if (p == lineEnd) break;
            const char* tokenEnd = p;
            while (tokenEnd < lineEnd && !blank(*tokenEnd))
                ++tokenEnd;
            // std::from_chars first (several times faster than strtod); what it does not take
            // whole (a leading '+', hexadecimal floats) is read by strtod, as before.
            double v = 0;
            const auto [ptr, ec] = std::from_chars(p, tokenEnd, v);
            if (ec == std::errc() && ptr == tokenEnd && std::isfinite(v)) {
                p = tokenEnd;
                continue;
            }
            const std::string token(p, tokenEnd);
            p = tokenEnd;
            char* parsed = nullptr;
            v = std::strtod(token.c_str(), &parsed);
            const bool number = parsed == token.c_str() + token.size();
            if (number && std::isfinite(v)) continue;
            throw InputError(file.string() + ": line " + std::to_string(lineNumber) + ": " + what +
                             ": \"" + token.substr(0, 40) + "\" is " +
                             (number ? "not a finite number" : "not a number"));
        }
    }
}

// A face corner written with a trailing slash and nothing after it ("1/1/", "1//"), which
// some exporters write and Mitsuba 3 reads (its test meshes hold one), means no normal (and no
// uv): tinyobjloader refuses it as a zero index. Such slashes are dropped from the face lines;
// the text is copied only when it has one.
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::string withoutTrailingCornerSlashes(const std::string& text) {
    bool found = false;
    for (std::size_t i = text.find('/'); i != std::string::npos && !found;
         i = text.find('/', i + 1))
        found = i + 1 == text.size() || isSpace(text[i + 1]);
    if (!found) return {};
    std::string out;
    out.reserve(text.size());
    std::size_t lineStart = 0;
    while (lineStart < text.size()) {
        std::size_t lineEnd = text.find('\n', lineStart);
        if (lineEnd == std::string::npos) lineEnd = text.size();
        std::size_t first = lineStart;
        while (first < lineEnd && (text[first] == ' ' || text[first] == '\t'))
            ++first;
        const bool face = first + 1 < lineEnd && text[first] == 'f' && isSpace(text[first + 1]);
        for (std::size_t i = lineStart; i < lineEnd; ++i) {
            if (face && text[i] == '/') {
                std::size_t j = i;
                while (j < lineEnd && text[j] == '/')
                    ++j;
                if (j == lineEnd || isSpace(text[j])) {
                    i = j - 1;  // a run of slashes ending the corner: dropped
                    continue;
                }
            }
            out += text[i];
        }
        if (lineEnd < text.size()) out += '\n';
        lineStart = lineEnd + 1;
    }
    return out;
}

tinyobj::ObjReader parseObj(const std::filesystem::path& file, const std::string& text,
                            const std::string& mtlText) {
    checkAttributeNumbers(file, text);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    const std::string cleaned = withoutTrailingCornerSlashes(text);
    if (!reader.ParseFromString(cleaned.empty() ? text : cleaned, mtlText, config))
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
    std::map<int, SharedCorners> unique;  // per key
    bool hasNormals = normals > 0, hasUvs = uvs > 0;
    for (const auto& shape : reader.GetShapes())
        for (const auto& index : shape.mesh.indices) {
            hasNormals &= index.normal_index >= 0;
            hasUvs &= index.texcoord_index >= 0;
        }
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
            const auto face = [&] {
                return (shape.name.empty() ? std::string() : "object \"" + shape.name + "\", ") +
                       "triangle " + std::to_string(t / 3);
            };
            const int meshKey = keyOf(shape, t / 3);
            const auto [at, added] = meshOfKey.emplace(meshKey, meshes.size());
            if (added) meshes.emplace_back(meshKey, MeshDesc{});
            MeshDesc& mesh = meshes[at->second].second;
            SharedCorners& shared = unique.try_emplace(meshKey, positions).first->second;
            std::array<std::uint32_t, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                const auto& i = idx[t + std::size_t(k)];
                // OBJ indices in messages count from 1, as in the file.
                checkIndex(file, face, "vertex", i.vertex_index, positions, false);
                checkIndex(file, face, "normal", i.normal_index, normals, true);
                checkIndex(file, face, "texture coordinate", i.texcoord_index, uvs, true);
                const CornerKey key{i.vertex_index, hasNormals ? i.normal_index : -1,
                                    hasUvs ? i.texcoord_index : -1};
                bool inserted = false;
                const std::uint32_t vertex =
                    shared.vertexOf(key, std::uint32_t(mesh.positions.size()), inserted);
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
                tri[std::size_t(k)] = vertex;
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
