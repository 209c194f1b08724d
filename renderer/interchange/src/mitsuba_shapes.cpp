// Mitsuba 3 shapes and emitters -> lamina shapes and lights (mitsuba_translation.h). Defaults
// and conventions are those of the plugin documentation in mitsuba3 src/shapes/*.cpp and
// src/emitters/*.cpp.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "document_names.h"
#include "lamina/core/error.h"
#include "lamina/core/frame.h"
#include "mitsuba_bsdfs.h"
#include "mitsuba_translation.h"
#include "rounded_rotation.h"

namespace lamina::render::mitsuba {

namespace {

// Mitsuba's cube: [-1, 1]^3, outward normals (mitsuba3 src/shapes/cube.cpp), as an inline
// lamina mesh of six quads, counter-clockwise seen from outside (reversed by flip_normals).
Json cubeMesh(bool flipNormals) {
    Json positions = Json::array(), faces = Json::array();
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {1.0, -1.0}) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // e_a x e_b = e_axis
            const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            Json face = Json::array();
            for (int c = 0; c < 4; ++c) {
                double p[3];
                p[axis] = sign;
                p[a] = corners[c][0];
                p[b] = corners[c][1];
                face.push_back(positions.size());
                positions.push_back(Json::array({p[0], p[1], p[2]}));
            }
            // Seen from -e_axis the order above is clockwise: reverse it there.
            if ((sign < 0) != flipNormals) std::reverse(face.begin(), face.end());
            faces.push_back(face);
        }
    return {{"type", "mesh"}, {"positions", positions}, {"faces", faces}};
}

std::string path(Translation& t, const std::filesystem::path& file) {
    return documentPath(file, t.pathsRelativeTo);
}

// The material of a shape: its one `<bsdf>` (nested or a ref), or Mitsuba's default diffuse
// 0.5; `alpha` receives a mask's opacity.
Json shapeMaterial(Translation& t, Plugin& p, std::optional<Json>& alpha,
                   const SurfaceDirections* surface) {
    const auto bsdfs = p.objects("bsdf");
    if (bsdfs.size() > 1) p.fail("a shape takes one BSDF, got " + std::to_string(bsdfs.size()));
    if (bsdfs.empty()) return {{"type", "lambert"}, {"reflectance", 0.5}};
    const Element& bsdf = *bsdfs[0];
    // Mitsuba's null BSDF is an index-matched boundary: lamina's reserved "interface".
    if (const std::string* type = bsdf.attribute("type"); type && *type == "null") {
        Plugin(bsdf, t.document, t.diagnostics).finish();
        return kDocumentInterfaceMaterial;
    }
    if (const auto it = t.namedBsdfs.find(&bsdf); it != t.namedBsdfs.end()) {
        alpha = it->second;
        return *bsdf.attribute("id");
    }
    TranslatedBsdf translated = translateBsdf(bsdf, t.document, t.diagnostics, false, 0, surface);
    alpha = translated.alpha;
    addTextures(t, translated.textures);
    return translated.material;
}

Json radiance(Plugin& p, const char* name, double fallback) {
    const Json value = p.color(name, true).value_or(Json(fallback));
    const auto negative = [](const Json& v) {
        if (v.is_number()) return v.get<double>() < 0;
        if (v.is_array())
            for (const Json& c : v)
                if (c.get<double>() < 0) return true;
        return false;
    };
    if (negative(value)) p.fail(std::string("parameter \"") + name + "\" must be >= 0");
    return value;
}

glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}
glm::dvec3 transformVector(const glm::dmat4& m, const glm::dvec3& v) {
    return glm::dvec3(m * glm::dvec4(v, 0.0));
}
Json triple(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

// An envmap's orientation as lamina environment `transform` operations (map to world).
// mitsuba3 envmap.cpp looks a local direction d = to_world^-1 w up at u = atan2(d.x, -d.z) /
// 2 pi, v = acos(d.y) / pi; lamina at u = 1/2 + atan2(d'.x, d'.z) / 2 pi with the same v. With
// d' = (-d.x, d.y, d.z) the two agree for every d (atan2(-x, z) = -atan2(x, z) and
// atan2(x, -z) = pi - atan2(x, z) mod 2 pi), so lamina's map-to-world is to_world times the
// reflection x -> -x, applied first. Anything but a rotation or reflection in to_world (and
// a translation, which directions ignore) is refused.
Json environmentTransform(Plugin& p, const std::optional<Transform>& transform) {
    Json operations = Json::array({Json{{"scale", Json::array({-1, 1, 1})}}});
    if (!transform) return operations;
    glm::dmat3 r(transform->matrix);
    // Rounded as exported files write a rotation (rounded_rotation.h).
    const double skew = columnSkew(r), scale = columnScaleError(r);
    if (skew > kRoundedRotationTolerance || scale > kRoundedRotationTolerance)
        p.fail("to_world of an envmap must be a rotation (lamina refuses a scale or shear)");
    if (skew > 1e-9 || scale > 1e-9) {
        p.warn("to_world of the envmap is a rotation to within " +
               deviationText(std::max(skew, scale)) +
               " (rounded digits): its nearest rotation is used");
        r = orthonormalised(r);
    }
    bool rotationsOnly = true;
    for (const Json& op : transform->operations)
        rotationsOnly &= op.contains("rotate");
    if (rotationsOnly) {
        for (const Json& op : transform->operations)
            operations.push_back(op);
        return operations;
    }
    Json rows = Json::array();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            rows.push_back(row < 3 && col < 3 ? r[col][row] : (row == col ? 1.0 : 0.0));
    operations.push_back(Json{{"matrix", rows}});
    return operations;
}

// Mitsuba's cylinder (mitsuba3 src/shapes/cylinder.cpp): radius 1 about the segment from p0
// (0, 0, 0) to p1 (0, 0, 1), open (no caps), facing outwards. Its to_world becomes to_world *
// translate(p0) * to_frame(Frame3f(d / |d|)) * scale(radius, radius, |d|) for d = p1 - p0,
// which places the unit cylinder (z in [0, 1]) with uv = (phi / 2 pi, z); Frame3f is Duff et
// al.'s basis, as lamina's Frame::fromNormal. That is a lamina cylinder of the placed radius,
// z in [0, length], in the placed frame. Its normal is the cross product of the placed dp/du
// and dp/dv: under a mirroring to_world it faces inwards, where lamina's faces outwards
// whatever the handedness, so flip_normals turns it then.
Json cylinderShape(Plugin& p) {
    const glm::dvec3 p0 = p.point("p0").value_or(glm::dvec3(0.0));
    const glm::dvec3 p1 = p.point("p1").value_or(glm::dvec3(0, 0, 1));
    const double radius = p.number("radius", 1.0);
    const bool flip = p.boolean("flip_normals", false);
    if (!(radius > 0)) p.fail("radius must be > 0");
    const double length = glm::length(p1 - p0);
    if (!(length > 0)) p.fail("p0 and p1 coincide: the cylinder has no length");
    const auto transform = p.transform("to_world");
    const glm::dmat4 toWorld = transform ? transform->matrix : glm::dmat4(1.0);
    const Frame<double> frame = Frame<double>::fromNormal((p1 - p0) / length);
    const glm::dmat3 a =
        glm::dmat3(toWorld) * glm::dmat3(frame.s * radius, frame.t * radius, frame.n * length);
    const double rx = glm::length(a[0]), ry = glm::length(a[1]), placedLength = glm::length(a[2]);
    // Round: to_world may rotate, mirror and scale, along the axis as it likes, but across it
    // alike in every direction (Mitsuba warns otherwise and renders the nearest such cylinder).
    const glm::dmat3 unit(a[0] / rx, a[1] / ry, a[2] / placedLength);
    const double deviation = std::max(columnSkew(unit), std::abs(rx - ry) / rx);
    if (!(deviation <= kRoundedRotationTolerance))
        p.fail(
            "to_world must keep the cylinder round (a rotation, a translation and a scale the "
            "same across its axis): lamina refuses a shear or an uneven scale across it");
    if (deviation > 1e-9)
        p.warn("to_world of the cylinder keeps it round to within " + deviationText(deviation) +
               " (rounded digits): the nearest round cylinder is used");
    const glm::dmat3 r = orthonormalised(unit);
    const glm::dvec3 origin = transformPoint(toWorld, p0);
    Json rows = Json::array();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            rows.push_back(row == 3   ? (col == 3 ? 1.0 : 0.0)
                           : col == 3 ? origin[row]
                                      : r[col][row]);
    Json s{{"type", "cylinder"},
           {"radius", 0.5 * (rx + ry)},
           {"z_min", 0.0},
           {"z_max", placedLength},
           {"transform", Json::array({Json{{"matrix", rows}}})}};
    if (flip != (glm::determinant(r) < 0)) s["flip_normals"] = true;
    return s;
}

}  // namespace

void addTextures(Translation& t, const std::vector<TranslatedTexture>& textures) {
    for (const TranslatedTexture& texture : textures) {
        Json definition = texture.texture;
        if (!texture.file.empty()) definition["file"] = path(t, texture.file);
        t.scene["textures"][texture.name] = std::move(definition);
    }
}

void translateShape(Translation& t, const Element& e, Json& out, bool inGroup) {
    Plugin p(e, t.document, t.diagnostics);
    const std::string& type = p.type();
    Json s = Json::object();
    if (type == "obj" || type == "ply" || type == "serialized") {
        const auto file = p.file("filename");
        if (!file) p.fail("needs a filename");
        s = {{"type", type}, {"file", path(t, *file)}};
        if (type == "serialized") {
            const long index = p.integer("shape_index", 0);
            if (index < 0 || index > (1L << 30)) p.fail("shape_index must be in [0, 2^30]");
            if (index != 0) s["shape_index"] = index;
        }
        if (p.boolean("flip_normals", false))
            p.fail("flip_normals is not supported on meshes (lamina meshes face as wound)");
        if (p.boolean("face_normals", false))
            p.warn("face_normals became the file's own normals (lamina uses them when present)");
        // Mitsuba's bitmaps put v = 0 at the top row and lamina's at the bottom row, so they
        // agree where Mitsuba flips v on reading (v -> 1 - v: OBJ's default, PLY's option).
        const bool flipV = type != "serialized" && p.boolean("flip_tex_coords", type == "obj");
        if (type == "obj" && !flipV)
            p.warn(
                "flip_tex_coords false: a bitmap on this mesh lands mirrored in v (lamina "
                "agrees with Mitsuba's flipped v)");
    } else if (type == "rectangle") {
        s = {{"type", "rectangle"}};
    } else if (type == "cube") {
        s = cubeMesh(p.boolean("flip_normals", false));
    } else if (type == "sphere") {
        const glm::dvec3 center = p.point("center").value_or(glm::dvec3(0.0));
        s = {{"type", "sphere"}, {"center", triple(center)}, {"radius", p.number("radius", 1.0)}};
        if (p.boolean("flip_normals", false)) s["flip_normals"] = true;
    } else if (type == "disk") {
        s = {{"type", "disk"}};
        if (p.boolean("flip_normals", false)) s["normal"] = Json::array({0.0, 0.0, -1.0});
    } else if (type == "cylinder") {
        s = cylinderShape(p);
    } else if (type == "bsplinecurve" || type == "linearcurve") {
        s = curveShape(t, p);
    } else if (type == "instance") {
        const auto groups = p.objects("shape");
        if (groups.size() != 1 || groups[0]->attribute("type") == nullptr ||
            *groups[0]->attribute("type") != "shapegroup" || !groups[0]->attribute("id"))
            p.fail("an instance needs one <ref> to a shapegroup with an id");
        if (inGroup) p.fail("an instance inside a shapegroup is not supported");
        s = {{"type", "instance"}, {"object", *groups[0]->attribute("id")}};
    } else {
        p.fail("the shape plugin \"" + type +
               "\" is not supported (obj, ply, serialized, rectangle, cube, sphere, disk, "
               "cylinder, bsplinecurve, linearcurve, instance, shapegroup)");
    }
    if (const std::string* id = e.attribute("id")) s["name"] = *id;
    if (type == "cylinder" || s.value("type", "") == "curves") {
        // Placed by cylinderShape (its transform holds p0, p1 and radius) and curveShape (its
        // control points are in world space).
    } else if (const auto transform = p.transform("to_world")) {
        Json operations = transform->operations;
        if (type == "rectangle" && p.boolean("flip_normals", false))
            operations.insert(operations.begin(),
                              Json{{"rotate", {{"axis", {1.0, 0.0, 0.0}}, {"angle", 180.0}}}});
        if (!operations.empty()) s["transform"] = operations;
    } else if (type == "rectangle" && p.boolean("flip_normals", false)) {
        // Turned over about x: the same square, facing -z.
        s["transform"] =
            Json::array({Json{{"rotate", {{"axis", {1.0, 0.0, 0.0}}, {"angle", 180.0}}}}});
    }
    if (type != "instance") {
        // A rectangle's u and v run along its to_world's x and y everywhere (mitsuba3
        // src/shapes/rectangle.cpp: dp_du = to_world (2, 0, 0), dp_dv = to_world (0, 2, 0)).
        std::optional<SurfaceDirections> surface;
        if (type == "rectangle") {
            const glm::dmat4 m = p.transform("to_world").value_or(Transform{}).matrix;
            const glm::dvec3 u(m[0]), v(m[1]);
            if (glm::length(u) > 0 && glm::length(v) > 0)
                surface = SurfaceDirections{glm::normalize(u), glm::normalize(v)};
        }
        std::optional<Json> alpha;
        s["material"] = shapeMaterial(t, p, alpha, surface ? &*surface : nullptr);
        if (s["type"] == "curves") warnCurveTextures(t, p, s["material"]);
        shapeMedia(t, p, s);
        if (s["material"] == kDocumentInterfaceMaterial && !s.contains("interior") &&
            !s.contains("exterior")) {
            // An interface between no media: Mitsuba's rays pass through it.
            p.objects("emitter");
            p.warn("a shape with the null BSDF and no medium omitted: it is invisible");
            p.finish();
            return;
        }
        const auto emitters = p.objects("emitter");
        if (emitters.size() > 1) p.fail("a shape takes one emitter");
        if (!emitters.empty()) {
            t.areaEmitters.insert(emitters[0]);
            Plugin emitter(*emitters[0], t.document, t.diagnostics);
            if (emitter.type() != "area")
                emitter.fail("only an area emitter can be attached to a shape");
            if (inGroup) emitter.fail("an emitting shape inside a shapegroup is not supported");
            if (s.value("type", "") == "curves")
                emitter.fail("an emitting curve is not supported (lamina's curves do not emit)");
            s["emission"] = {{"radiance", radiance(emitter, "radiance", 1.0)}};
            emitter.finish();
        }
        if (alpha) {
            if (!emitters.empty()) p.fail("a mask on an emitting shape is not supported");
            const std::string kind = s.value("type", "");
            if (alpha->is_object() &&
                (kind == "sphere" || kind == "disk" || kind == "cylinder" || kind == "curves"))
                p.fail("a textured mask opacity on a " + kind +
                       " is not supported (lamina reads a texture alpha at a triangle mesh's "
                       "uv; give a number)");
            s["alpha"] = *alpha;
        }
    }
    p.finish();
    out.push_back(s);
}

void translateShapeGroup(Translation& t, const Element& group) {
    Plugin p(group, t.document, t.diagnostics);
    const std::string* id = group.attribute("id");
    if (!id) p.fail("a shapegroup needs an id");
    Json shapes = Json::array();
    for (const Element* shape : p.objects("shape"))
        translateShape(t, *shape, shapes, true);
    if (shapes.empty()) p.fail("an empty shapegroup");
    p.finish();
    t.scene["objects"][*id] = shapes;
}

void translateEmitter(Translation& t, const Element& e) {
    Plugin p(e, t.document, t.diagnostics);
    const std::string& type = p.type();
    const auto transform = p.transform("to_world");
    const glm::dmat4 toWorld = transform ? transform->matrix : glm::dmat4(1.0);
    Json light;
    if (type == "point") {
        if (transform && p.has("position")) p.fail("give position or to_world, not both");
        const glm::dvec3 position =
            p.point("position").value_or(transformPoint(toWorld, glm::dvec3(0.0)));
        light = {{"type", "point"},
                 {"position", triple(position)},
                 {"intensity", radiance(p, "intensity", 1.0)}};
    } else if (type == "spot") {
        // mitsuba3 spot.cpp: at the origin of to_world, along its +z; cutoff_angle 20 degrees,
        // beam_width 3/4 of it, falloff linear in the angle between the two.
        const double cutoff = p.number("cutoff_angle", 20.0);
        const double beam = p.number("beam_width", cutoff * 0.75);
        if (!(cutoff > 0 && cutoff < 180) || !(beam >= 0 && beam <= cutoff))
            p.fail("needs 0 < beam_width <= cutoff_angle < 180 degrees");
        const glm::dvec3 position = transformPoint(toWorld, glm::dvec3(0.0));
        const glm::dvec3 direction = transformVector(toWorld, glm::dvec3(0, 0, 1));
        if (glm::length(direction) == 0) p.fail("to_world maps +z to zero");
        light = {{"type", "spot"},
                 {"position", triple(position)},
                 {"look_at", triple(position + glm::normalize(direction))},
                 {"intensity", radiance(p, "intensity", 1.0)},
                 {"cone_angle", cutoff},
                 {"falloff_start", beam}};
        p.warn(
            "spot became lamina's spot: the falloff between beam_width and cutoff_angle is a "
            "smoothstep in cos theta (Mitsuba's is linear in the angle)");
    } else if (type == "directional") {
        // mitsuba3 directional.cpp: `direction` (where the light travels) or to_world's +z.
        if (transform && p.has("direction")) p.fail("give direction or to_world, not both");
        const glm::dvec3 direction =
            p.point("direction").value_or(transformVector(toWorld, glm::dvec3(0, 0, 1)));
        if (glm::length(direction) == 0) p.fail("the direction is zero");
        light = {{"type", "directional"},
                 {"direction", triple(direction)},
                 {"irradiance", radiance(p, "irradiance", 1.0)}};
    } else if (type == "constant") {
        light = {{"type", "environment"}, {"radiance", radiance(p, "radiance", 1.0)}};
    } else if (type == "envmap") {
        const auto file = p.file("filename");
        if (!file) p.fail("needs a filename");
        light = {{"type", "environment"}, {"file", path(t, *file)}};
        const double scale = p.number("scale", 1.0);
        if (!(scale >= 0)) p.fail("scale must be >= 0");
        if (scale != 1.0) light["scale"] = scale;
        light["transform"] = environmentTransform(p, transform);
        p.ignore("mis_compensation", "lamina samples the map by luminance x sin theta");
    } else if (type == "area") {
        p.fail("an area emitter must be nested in a shape");
    } else {
        p.fail("the emitter plugin \"" + type +
               "\" is not supported (area, point, spot, directional, constant, envmap)");
    }
    if (endpointMedium(t, p))
        p.warn(
            "the emitter's medium is not written: lamina finds the medium a light sits in "
            "from the boundaries around it");
    p.finish();
    t.scene["lights"].push_back(light);
}

}  // namespace lamina::render::mitsuba
