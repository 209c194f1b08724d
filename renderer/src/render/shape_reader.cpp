#include <glm/gtc/matrix_transform.hpp>

#include "lamina/render/mesh_files.h"
#include "lamina/render/scene_readers.h"

namespace lamina::render {

// "transform": a list of operations applied in order (the first one first):
// {"translate": [x, y, z]}, {"scale": s | [x, y, z]}, {"rotate": {"axis": [x, y, z],
// "angle": degrees}}, {"matrix": [16 numbers, row-major]}.
Mat4 readTransform(const JsonReader& parent) {
    Mat4 m(1.0);
    const auto t = parent.optionalChild("transform");
    if (!t) return m;
    if (!t->value().is_array()) t->fail("expected an array of operations");
    for (std::size_t i = 0; i < t->value().size(); ++i) {
        const JsonReader op(t->value()[i], t->indexPath(i), t->source());
        op.expectObject();
        if (op.value().size() != 1)
            op.fail("expected one operation: translate, scale, rotate or matrix");
        Mat4 step(1.0);
        if (op.has("translate")) {
            step = glm::translate(Mat4(1.0), requiredVec3(op, "translate"));
        } else if (op.has("scale")) {
            const auto s = op.optionalTriple("scale");
            if ((*s)[0] == 0 || (*s)[1] == 0 || (*s)[2] == 0)
                op.failAt("scale", "a scale of 0 collapses the shape");
            step = glm::scale(Mat4(1.0), Vec3d((*s)[0], (*s)[1], (*s)[2]));
        } else if (op.has("rotate")) {
            const JsonReader rot = op.child("rotate");
            const Vec3d axis = requiredVec3(rot, "axis");
            if (glm::length(axis) == 0) rot.failAt("axis", "expected a non-zero axis");
            const double angle = rot.requiredNumber("angle");
            rot.finish();
            step = glm::rotate(Mat4(1.0), glm::radians(angle), glm::normalize(axis));
        } else if (op.has("matrix")) {
            step = requiredMatrix(op, "matrix");
            if (std::abs(glm::determinant(step)) < 1e-300) op.failAt("matrix", "is singular");
        } else {
            op.fail("expected one of translate, scale, rotate, matrix");
        }
        op.finish();
        m = step * m;
    }
    return m;
}

namespace {

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
            mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
            mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
            mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            mesh.isRectangle = true;
            break;
        case ShapeKind::Sphere:
        case ShapeKind::Disk:
            break;  // analytic: no triangles
    }
}

void finishMesh(const JsonReader& r, MeshDesc mesh, const Mat4& m, SceneDesc& scene) {
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
    scene.meshes.push_back(std::move(mesh));
}

}  // namespace

void readShape(const JsonReader& r, SceneMaterials& materials, SceneDesc& scene) {
    r.expectObject();
    r.noteNames("type", kShapeKindNames.names());
    const std::string type = r.requiredString("type");
    const std::string name = r.string("name", r.path());
    const auto kind = kShapeKindNames.find(type);
    if (!kind)
        r.failAt("type", "expected one of " + kShapeKindNames.list() + "; got \"" + type + "\"");
    if (*kind == ShapeKind::Sphere) {
        scene.spheres.push_back(readSphere(r, name, materials));
        return;
    }
    if (*kind == ShapeKind::Disk) {
        scene.disks.push_back(readDisk(r, name, materials));
        return;
    }
    MeshDesc mesh;
    mesh.name = name;
    readTriangles(r, *kind, mesh);
    mesh.material = materials.materialOf(r);
    mesh.emission = readEmission(r);
    const Mat4 m = readTransform(r);
    r.finish();
    finishMesh(r, std::move(mesh), m, scene);
}

}  // namespace lamina::render
