#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "lamina/scene/mesh_files.h"
#include "lamina/scene/obj_materials.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

namespace {

// Where a shape's description goes: the scene's top-level lists or an object's.
struct ShapeLists {
    std::vector<MeshDesc>& meshes;
    std::vector<SphereDesc>& spheres;
    std::vector<DiskDesc>& disks;
    /// Where what a reader maps to something else is said (SceneDesc::importWarnings).
    std::vector<std::string>& warnings;
};

// "alpha": a number in [0, 1] or {"texture": "name"} (its first channel).
AlphaDesc readAlpha(const JsonReader& r, SceneMaterials& materials) {
    AlphaDesc alpha;
    if (!r.has("alpha")) return alpha;
    // An emitter's light sampling knows nothing of holes in it: a cut-out emitter would be
    // sampled where it is not.
    if (r.has("emission"))
        r.failAt("alpha", "an emitting shape cannot be cut out (remove alpha or emission)");
    const JsonReader a = r.child("alpha");
    if (a.value().is_object()) {
        const std::string name = a.requiredString("texture");
        a.finish();
        alpha.texture = materials.textureIndex(a, "texture", name);
        return alpha;
    }
    if (!a.value().is_number()) a.fail("expected a number in [0, 1] or {\"texture\": \"name\"}");
    alpha.value = float(r.number("alpha", 1.0, Range::unit()));
    return alpha;
}

// Analytic shapes take similarity transforms only: returns the uniform scale.
double uniformScale(const JsonReader& r, const Mat4& m, const std::string& what) {
    const double sx = glm::length(Vec3d(m[0])), sy = glm::length(Vec3d(m[1])),
                 sz = glm::length(Vec3d(m[2]));
    if (std::abs(sx - sy) > 1e-9 * sx || std::abs(sx - sz) > 1e-9 * sx)
        r.failAt("transform", what + " takes translate, rotate and uniform scale only");
    return sx;
}

SphereDesc readSphere(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    SphereDesc s;
    s.name = name;
    s.center = readVec3(r, "center", Vec3d(0.0));
    s.radius = r.number("radius", 1.0, Range::positive());
    s.flipNormals = r.boolean("flip_normals", false);
    s.material = materials.materialOf(r);
    s.emission = readEmission(r);
    s.alpha = readAlpha(r, materials);
    if (s.alpha.texture >= 0)
        r.failAt("alpha",
                 "a texture alpha is read at a triangle shape's uv; a sphere takes a number");
    const Mat4 m = readTransform(r);
    const double sx = uniformScale(r, m, "a sphere");
    s.center = Vec3d(m * glm::dvec4(s.center, 1.0));
    s.radius *= sx;
    checkCoordinates(r, "center", glm::abs(s.center) + s.radius,
                     "the sphere's bounding box corner");
    if (s.emission) checkEmitterArea(r, 4.0 * kPi<double> * s.radius * s.radius);
    r.finish();
    return s;
}

DiskDesc readDisk(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    // The unit disk in the plane z = 0 facing +z, or centre / normal / radius.
    DiskDesc d;
    d.name = name;
    d.center = readVec3(r, "center", Vec3d(0.0));
    d.normal = readVec3(r, "normal", Vec3d(0, 0, 1));
    if (glm::length(d.normal) == 0) r.failAt("normal", "expected a non-zero vector");
    d.normal = glm::normalize(d.normal);
    d.radius = r.number("radius", 1.0, Range::positive());
    d.material = materials.materialOf(r);
    d.emission = readEmission(r);
    d.alpha = readAlpha(r, materials);
    if (d.alpha.texture >= 0)
        r.failAt("alpha",
                 "a texture alpha is read at a triangle shape's uv; a disk takes a number");
    const Mat4 m = readTransform(r);
    const double sx = uniformScale(r, m, "a disk");
    d.center = Vec3d(m * glm::dvec4(d.center, 1.0));
    d.normal = glm::normalize(glm::dmat3(m) * d.normal) *
               (glm::determinant(glm::dmat3(m)) < 0 ? -1.0 : 1.0);
    d.radius *= sx;
    checkCoordinates(r, "center", glm::abs(d.center) + d.radius, "the disk's bounding box corner");
    if (d.emission) checkEmitterArea(r, kPi<double> * d.radius * d.radius);
    r.finish();
    return d;
}

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
        case ShapeKind::Rectangle:
            // The square [-1, 1]^2 in the plane z = 0, facing +z; place it with `transform`.
            // An emitting one is one light (RectangleLight::isRectangle).
            mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
            mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
            mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            break;
        case ShapeKind::Sphere:
        case ShapeKind::Disk:
        case ShapeKind::Instance:
            break;  // analytic, or an object's: no triangles of its own
    }
}

void finishMesh(const JsonReader& r, MeshDesc mesh, const Mat4& m, ShapeLists& lists) {
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3d p = Vec3d(m * glm::dvec4(Vec3d(mesh.positions[i]), 1.0));
        checkCoordinates(r,
                         r.has("transform") ? "transform"
                         : r.has("file")    ? "file"
                                            : "positions",
                         p, "vertex " + std::to_string(i) + " at");
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
    lists.meshes.push_back(std::move(mesh));
}

// An "instance": an object placed by "transform". Its transformed bounding box must stay
// within float range, as every shape's coordinates do.
InstanceDesc readInstance(const JsonReader& r, const std::string& name, SceneObjects& objects,
                          SceneDesc& scene) {
    InstanceDesc instance;
    instance.name = name;
    instance.object = objects.objectOf(r);
    instance.toWorld = readTransform(r);
    r.finish();
    Vec3d lo, hi;
    boundingBox(scene.objects[std::size_t(instance.object)], lo, hi);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                      (corner & 4) ? hi.z : lo.z);
        checkCoordinates(r, "transform", Vec3d(instance.toWorld * glm::dvec4(p, 1.0)),
                         "the instance's bounding box corner");
    }
    return instance;
}

// An `obj` shape without a `material`: one mesh per usemtl group, each with the material its
// MTL entry maps to (obj_materials.h), named "MTLFILE:NAME"; the shape's emission, if any,
// applies to every group, else an entry's Ke.
void readObjWithMaterials(const JsonReader& r, const std::string& name, SceneMaterials& materials,
                          ShapeLists& lists) {
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
        finishMesh(r, std::move(mesh), m, lists);
    }
    lists.warnings.insert(lists.warnings.end(), obj.warnings.begin(), obj.warnings.end());
}

// One shape into `lists`; `inObject` refuses what an object cannot hold.
void readShapeInto(const JsonReader& r, SceneMaterials& materials, ShapeLists lists,
                   bool inObject) {
    r.expectObject();
    // The schema's surface shapes list every type but `instance` (a branch of its own).
    std::vector<std::string> surfaceKinds = kShapeKindNames.names();
    std::erase(surfaceKinds, std::string(kShapeKindNames.name(ShapeKind::Instance)));
    r.noteNames("type", surfaceKinds);
    const std::string type = r.requiredString("type");
    const std::string name = r.string("name", r.path());
    const auto kind = kShapeKindNames.find(type);
    if (!kind)
        r.failAt("type", "expected one of " + kShapeKindNames.list() + "; got \"" + type + "\"");
    if (inObject && *kind == ShapeKind::Instance)
        r.failAt("type",
                 "an instance inside an object is refused: objects hold shapes, one level deep "
                 "(place the inner object's shapes in the object, or instance it at the top)");
    // pbrt-v4 does not support area lights in instances either (its scene builder warns
    // "Area lights not supported with object instancing" and drops them, src/pbrt/scene.cpp).
    if (inObject && r.has("emission"))
        r.failAt("emission",
                 "an emitting shape inside an object is refused: instanced area lights are not "
                 "supported (place the emitter in \"shapes\")");
    if (*kind == ShapeKind::Sphere) {
        lists.spheres.push_back(readSphere(r, name, materials));
        return;
    }
    if (*kind == ShapeKind::Disk) {
        lists.disks.push_back(readDisk(r, name, materials));
        return;
    }
    if (*kind == ShapeKind::Obj && !r.has("material")) {
        readObjWithMaterials(r, name, materials, lists);
        return;
    }
    MeshDesc mesh;
    mesh.name = name;
    readTriangles(r, *kind, mesh);
    mesh.material = materials.materialOf(r);
    mesh.emission = readEmission(r);
    mesh.alpha = readAlpha(r, materials);
    const Mat4 m = readTransform(r);
    r.finish();
    finishMesh(r, std::move(mesh), m, lists);
}

}  // namespace

void readShape(const JsonReader& r, SceneMaterials& materials, SceneObjects& objects,
               SceneDesc& scene) {
    if (r.value().is_object() && r.value().value("type", Json()) == "instance") {
        r.requiredString("type");
        const std::string name = r.string("name", r.path());
        scene.instances.push_back(readInstance(r, name, objects, scene));
        return;
    }
    readShapeInto(r, materials, {scene.meshes, scene.spheres, scene.disks, scene.importWarnings},
                  false);
}

void SceneObjects::define(const JsonReader& objects) {
    objects.expectObject();
    for (const auto& [name, value] : objects.value().items())
        objects_.emplace_back(name, objects.child(name));
    objects.finish();
}

int SceneObjects::objectOf(const JsonReader& instance) {
    const std::string name = instance.requiredString("object");
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
        if (scene_.objects[i].name == name) return int(i);
    for (const auto& [definedName, reader] : objects_) {
        if (definedName != name) continue;
        if (!reader.value().is_array() || reader.value().empty())
            reader.fail("expected a non-empty array of shapes");
        ObjectDesc object;
        object.name = name;
        for (std::size_t i = 0; i < reader.value().size(); ++i)
            readShapeInto(
                JsonReader(reader.value()[i], reader.indexPath(i), reader.source()), materials_,
                {object.meshes, object.spheres, object.disks, scene_.importWarnings}, true);
        // An OBJ's MTL can make a group emit (Ke) without an "emission" key.
        for (const MeshDesc& mesh : object.meshes)
            if (mesh.emission)
                reader.fail("the object's mesh \"" + mesh.name +
                            "\" emits (an MTL Ke): instanced area lights are not supported");
        scene_.objects.push_back(std::move(object));
        return int(scene_.objects.size() - 1);
    }
    std::string known;
    for (const auto& [n, reader] : objects_)
        known += (known.empty() ? "" : ", ") + n;
    instance.failAt(
        "object", "unknown object \"" + name + "\"" +
                      (known.empty() ? " (the scene defines no objects)" : "; defined: " + known));
}

void SceneObjects::recordUnused() {
    // A plain loop variable, not a structured binding: clang 14 refuses lambdas that capture
    // structured bindings (a C++20 feature it lacks).
    for (const auto& entry : objects_) {
        const std::string& name = entry.first;
        if (std::none_of(scene_.objects.begin(), scene_.objects.end(),
                         [&](const ObjectDesc& o) { return o.name == name; }))
            scene_.unusedObjectNames.push_back(name);
    }
}

}  // namespace lamina::render
