// The entries of "shapes" and "objects": the type, instances and the objects they place; the
// analytic shapes are analytic_shape_reader.cpp's, the triangle meshes mesh_shape_reader.cpp's.
#include <algorithm>

#include "shape_readers.h"

namespace lamina::render {

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

namespace {

// A moving instance's matrix, interpolated linearly from `start` to `end`, must stay
// invertible at every time (the hit is carried back through its inverse): its linear part's
// determinant, a cubic in the time, keeps one sign, checked at 65 times (a rotation by 180
// degrees, which passes through a singular matrix halfway, is refused).
void checkMotion(const JsonReader& r, const Mat4& start, const Mat4& end) {
    const double d0 = glm::determinant(glm::dmat3(start)), d1 = glm::determinant(glm::dmat3(end));
    const double floor = 1e-6 * std::min(std::abs(d0), std::abs(d1));
    for (int i = 0; i <= 64; ++i) {
        const double t = i / 64.0;
        const double d = glm::determinant(glm::dmat3((1 - t) * start + t * end));
        if (!(d * d0 > 0) || !(std::abs(d) > floor))
            r.failAt("transform_end",
                     "the motion from transform to transform_end passes through a flat (singular) "
                     "matrix at time " +
                         std::to_string(t) +
                         " (matrices are interpolated element by element: split a large rotation "
                         "into instances of smaller steps, or turn by less than 90 degrees)");
    }
}

// An "instance": an object placed by "transform". Its transformed bounding box must stay
// within float range, as every shape's coordinates do.
InstanceDesc readInstance(const JsonReader& r, const std::string& name, SceneObjects& objects,
                          SceneDesc& scene) {
    InstanceDesc instance;
    instance.name = name;
    instance.object = objects.objectOf(r);
    instance.toWorld = readTransform(r);
    if (r.has("transform_end")) {
        instance.toWorldEnd = readTransform(r, "transform_end");
        checkMotion(r, instance.toWorld, *instance.toWorldEnd);
    }
    r.finish();
    Vec3d lo, hi;
    boundingBox(scene.objects[std::size_t(instance.object)].shapes, lo, hi);
    for (int corner = 0; corner < 16; ++corner) {
        const Vec3d p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                      (corner & 4) ? hi.z : lo.z);
        const bool end = (corner & 8) != 0;
        if (end && !instance.toWorldEnd) continue;
        checkCoordinates(
            r, end ? "transform_end" : "transform",
            Vec3d((end ? *instance.toWorldEnd : instance.toWorld) * glm::dvec4(p, 1.0)),
            "the instance's bounding box corner");
    }
    return instance;
}

// One shape into `to`; `inObject` refuses what an object cannot hold.
void readShapeInto(const JsonReader& r, SceneMaterials& materials, const ShapeDestination& to,
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
    // Read before the shape's own reader finishes (and refuses keys it did not read).
    const auto media = readMediumInterface(r, materials.scene().media);
    const std::size_t first = to.shapes.size();
    if (*kind == ShapeKind::Sphere)
        to.shapes.push_back(readSphere(r, name, materials));
    else if (*kind == ShapeKind::Disk)
        to.shapes.push_back(readDisk(r, name, materials));
    else if (*kind == ShapeKind::Cylinder)
        to.shapes.push_back(readCylinder(r, name, materials));
    else if (*kind == ShapeKind::Curves)
        to.shapes.push_back(readCurves(r, name, materials));
    else
        readMeshShape(r, *kind, name, materials, to);
    for (std::size_t i = first; i < to.shapes.size(); ++i) {
        SurfaceDesc& surface = render::surface(to.shapes[i]);
        surface.media = media;
        if (!surface.isInterface()) continue;
        // An interface only changes the medium: light sampling knows nothing of it.
        if (surface.emission)
            r.failAt("emission", "an \"interface\" shape does not emit (give it a material)");
        if (!media)
            r.failAt("material",
                     "an \"interface\" shape needs \"interior\" or \"exterior\" (the media it "
                     "separates; docs/media.md)");
    }
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
    readShapeInto(r, materials, {scene.shapes, scene.importWarnings}, false);
}

bool SceneDesc::hasMotion() const {
    return std::any_of(instances.begin(), instances.end(),
                       [](const InstanceDesc& i) { return i.toWorldEnd.has_value(); });
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
            readShapeInto(JsonReader(reader.value()[i], reader.indexPath(i), reader.source()),
                          materials_, {object.shapes, scene_.importWarnings}, true);
        orderShapesByKind(object.shapes);
        // An OBJ's MTL can make a group emit (Ke) without an "emission" key.
        for (const ShapeDesc& shape : object.shapes)
            if (const auto* mesh = std::get_if<MeshDesc>(&shape); mesh && mesh->emission)
                reader.fail("the object's mesh \"" + mesh->name +
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
