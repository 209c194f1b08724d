// The triangle-mesh shapes of "shapes" (`mesh`, `rectangle`, `obj`, `ply`, `serialized`): their
// triangles inline, from a file or made here, placed by the shape's transform.
#include <glm/gtc/matrix_transform.hpp>

#include "lamina/scene/mesh_files.h"
#include "lamina/scene/obj_materials.h"
#include "shape_readers.h"

namespace lamina::render {

namespace {

void readInlineMesh(const JsonReader& r, MeshDesc& mesh) {
    const JsonReader pos = r.child("positions");
    if (!pos.value().is_array() || pos.value().size() < 3)
        pos.fail("expected an array of at least 3 [x, y, z] positions");
    for (std::size_t i = 0; i < pos.value().size(); ++i) {
        const auto& v = pos.value()[i];
        if (!v.is_array() || v.size() != 3)
            pos.fail("expected [x, y, z] at index " + std::to_string(i));
        Vec3<float> p;
        for (int c = 0; c < 3; ++c)
            p[c] = float(pos.checkNumber(v[std::size_t(c)], pos.indexPath(i), Range::any()));
        mesh.positions.push_back(p);
    }
    // Optional per-vertex shading normals and uvs, one per position.
    auto perVertex = [&](const char* key, int n, auto& out) {
        if (!r.has(key)) return;
        const JsonReader list = r.child(key);
        if (!list.value().is_array() || list.value().size() != mesh.positions.size())
            list.fail("expected one entry per position (" + std::to_string(mesh.positions.size()) +
                      ")");
        for (std::size_t i = 0; i < list.value().size(); ++i) {
            const auto& v = list.value()[i];
            if (!v.is_array() || int(v.size()) != n)
                list.fail("expected " + std::to_string(n) + " numbers at index " +
                          std::to_string(i));
            typename std::decay_t<decltype(out)>::value_type e{};
            for (int c = 0; c < n; ++c)
                e[c] = float(list.checkNumber(v[std::size_t(c)], list.indexPath(i), Range::any()));
            out.push_back(e);
        }
    };
    perVertex("normals", 3, mesh.normals);
    perVertex("uvs", 2, mesh.uvs);
    for (const auto& n : mesh.normals)
        if (glm::length(n) == 0) r.failAt("normals", "a normal is zero");
    const JsonReader faces = r.child("faces");
    if (!faces.value().is_array() || faces.value().empty())
        faces.fail("expected an array of faces, each [i, j, k, ...] (a polygon)");
    for (std::size_t f = 0; f < faces.value().size(); ++f) {
        const auto& face = faces.value()[f];
        if (!face.is_array() || face.size() < 3)
            faces.fail("face " + std::to_string(f) + ": expected at least 3 indices");
        std::vector<std::uint32_t> idx;
        for (const auto& i : face) {
            if (!i.is_number_integer() || i.get<long long>() < 0 ||
                i.get<long long>() >= (long long)mesh.positions.size())
                faces.fail("face " + std::to_string(f) + ": expected vertex indices in [0, " +
                           std::to_string(mesh.positions.size() - 1) + "], got " + shortDump(i));
            idx.push_back(std::uint32_t(i.get<long long>()));
        }
        // Polygons (the Cornell box's quads) are split as fans: (0, 1, 2), (0, 2, 3), ...
        for (std::size_t k = 1; k + 1 < idx.size(); ++k)
            mesh.triangles.push_back({idx[0], idx[k], idx[k + 1]});
    }
}

void readMeshFile(const JsonReader& r, void (*read)(const std::filesystem::path&, MeshDesc&),
                  MeshDesc& mesh) {
    const std::filesystem::path file = r.filePath("file");
    try {
        read(file, mesh);
    } catch (const InputError& e) {
        r.failAt("file", e.what());
    }
}

// The triangles of a mesh shape, in the shape's own space.
void readTriangles(const JsonReader& r, ShapeKind kind, MeshDesc& mesh) {
    switch (kind) {
        case ShapeKind::Mesh:
            readInlineMesh(r, mesh);
            break;
        case ShapeKind::Obj:
            readMeshFile(r, readObj, mesh);
            break;
        case ShapeKind::Ply:
            readMeshFile(r, readPly, mesh);
            break;
        case ShapeKind::Serialized: {
            // One mesh of a Mitsuba serialized file (its `shape_index`, 0 the first).
            const auto index = std::uint32_t(r.integer("shape_index", 0, 0, 1 << 30));
            const std::filesystem::path file = r.filePath("file");
            try {
                readSerialized(file, index, mesh);
            } catch (const InputError& e) {
                r.failAt("file", e.what());
            }
            break;
        }
        case ShapeKind::Rectangle:
            // The square [-1, 1]^2 in the plane z = 0, facing +z; place it with `transform`.
            // An emitting one is one light (RectangleLight::isRectangle).
            mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
            mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
            mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            break;
        case ShapeKind::Sphere:
        case ShapeKind::Disk:
        case ShapeKind::Cylinder:
        case ShapeKind::Instance:
        case ShapeKind::Curves:
            break;  // analytic, an object's or curves: no triangles of their own
    }
}

void finishMesh(const JsonReader& r, MeshDesc mesh, const Mat4& m, const ShapeDestination& to) {
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
    // The key a coordinate out of range is reported at, found once (not per vertex: a mesh
    // file has millions); the message is made only for the vertex that fails.
    const char* key = r.has("transform") ? "transform" : r.has("file") ? "file" : "positions";
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3d p = Vec3d(m * glm::dvec4(Vec3d(mesh.positions[i]), 1.0));
        if (!(std::abs(p.x) <= kMaxSceneCoordinate && std::abs(p.y) <= kMaxSceneCoordinate &&
              std::abs(p.z) <= kMaxSceneCoordinate))
            checkCoordinates(r, key, p, "vertex " + std::to_string(i) + " at");
        mesh.positions[i] = Vec3<float>(p);
    }
    for (auto& n : mesh.normals)
        n = Vec3<float>(glm::normalize(normalMatrix * Vec3d(n)));
    // A negative determinant mirrors the winding; keep the geometric normal outwards.
    if (glm::determinant(glm::dmat3(m)) < 0)
        for (auto& t : mesh.triangles)
            std::swap(t[1], t[2]);
    if (mesh.emission) {
        // Each triangle is a light of its own (light_set.cpp), with its area computed the
        // same way: a degenerate one is never sampled, a tiny one would have an infinite
        // density.
        double area = 0;
        for (const auto& t : mesh.triangles) {
            const double a =
                0.5 * glm::length(glm::cross(Vec3d(mesh.positions[t[1]] - mesh.positions[t[0]]),
                                             Vec3d(mesh.positions[t[2]] - mesh.positions[t[0]])));
            if (a > 0) checkEmitterArea(r, a);
            area += a;
        }
        checkEmitterArea(r, area);
    }
    to.shapes.push_back(std::move(mesh));
}

// An `obj` shape without a `material`: one mesh per usemtl group, each with the material its
// MTL entry maps to (obj_materials.h), named "MTLFILE:NAME"; the shape's emission, if any,
// applies to every group, else an entry's Ke.
void readObjWithMaterials(const JsonReader& r, const std::string& name, SceneMaterials& materials,
                          const ShapeDestination& to) {
    const std::filesystem::path file = r.filePath("file");
    ObjGroups obj;
    try {
        obj = readObjGroups(file);
    } catch (const InputError& e) {
        r.failAt("file", e.what());
    }
    if (r.source().readFiles)
        for (const auto& library : obj.libraries)
            r.source().readFiles->push_back(library);
    const std::optional<EmissionDesc> emission = readEmission(r);
    const AlphaDesc alpha = readAlpha(r, materials);
    const Mat4 m = readTransform(r);
    r.finish();
    for (auto& group : obj.groups) {
        MeshDesc mesh = std::move(group.mesh);
        mesh.alpha = alpha;
        if (group.material < 0) {
            const std::string materialName = file.string() + ":default";
            mesh.name = name + ":default";
            const JsonSource source{file.string(), file.parent_path(), r.source().readFiles};
            mesh.material = materials.generated(
                materialName, Json{{"type", "lambert"}, {"reflectance", 0.5}}, source);
        } else {
            const MtlMaterial& mtl = obj.materials[std::size_t(group.material)];
            mesh.name = name + ":" + mtl.mtlName;
            const JsonSource source{mtl.file.string() + ":" + std::to_string(mtl.line) +
                                        " (newmtl " + mtl.mtlName + ")",
                                    mtl.file.parent_path(), r.source().readFiles};
            std::vector<std::pair<std::string, Json>> textures;
            if (mtl.diffuseMap)
                textures.emplace_back(mtl.textureName,
                                      Json{{"type", "image"}, {"file", *mtl.diffuseMap}});
            mesh.material = materials.generated(mtl.name, mtl.material, source, textures);
            if (!emission && mtl.emission) mesh.emission = EmissionDesc{*mtl.emission, {}, false};
        }
        if (emission) mesh.emission = emission;
        finishMesh(r, std::move(mesh), m, to);
    }
    to.warnings.insert(to.warnings.end(), obj.warnings.begin(), obj.warnings.end());
}

}  // namespace

void readMeshShape(const JsonReader& r, ShapeKind kind, const std::string& name,
                   SceneMaterials& materials, const ShapeDestination& to) {
    if (kind == ShapeKind::Obj && !r.has("material")) {
        readObjWithMaterials(r, name, materials, to);
        return;
    }
    MeshDesc mesh;
    mesh.name = name;
    readTriangles(r, kind, mesh);
    mesh.material = materials.materialOf(r);
    mesh.emission = readEmission(r);
    mesh.alpha = readAlpha(r, materials);
    const Mat4 m = readTransform(r);
    r.finish();
    finishMesh(r, std::move(mesh), m, to);
}

}  // namespace lamina::render
