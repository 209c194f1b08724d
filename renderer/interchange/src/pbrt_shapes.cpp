// pbrt-v4 shapes and their area lights -> lamina shapes (pbrt-v4 shapes.cpp for the parameters
// and their defaults, lights.cpp for DiffuseAreaLight).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "document_names.h"
#include "lamina/core/error.h"
#include "pbrt_meshes.h"
#include "pbrt_shapes.h"
#include "rounded_rotation.h"

namespace lamina::render::pbrt {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool isIdentity(const glm::dmat4& m) {
    return m == glm::dmat4(1.0);
}

// The uniform scale of a similarity transform (a rotation or reflection times a uniform scale,
// with any translation), 0 if `m` is not one. Exported files round rotations to 6-8 digits: a
// matrix within kRoundedRotationTolerance of a similarity is taken as that similarity
// (`rounded` says by how much it deviated, for a warning).
double similarityScale(const glm::dmat4& m, double& rounded) {
    const glm::dmat3 a(m);
    const double s = std::cbrt(std::abs(glm::determinant(a)));
    if (!(s > 0)) return 0;
    rounded = std::max(columnSkew(a), columnScaleError(a / s));
    if (rounded > kRoundedRotationTolerance) return 0;
    // An exact similarity keeps the length of its x column, the scale written before rounded
    // transforms were taken (the same number to the last digit for shipped scenes).
    return rounded > 1e-9 ? s : glm::length(a[0]);
}

// A similarity of uniform scale `scale` made exact: its rotation (or reflection) the nearest
// orthonormal one (exported files round it to 6-8 digits; lamina's analytic shapes take exact
// similarities), its translation kept.
glm::dmat4 exactSimilarity(const glm::dmat4& m, double scale) {
    const glm::dmat3 r = orthonormalised(glm::dmat3(m) / scale);
    glm::dmat4 exact = m;
    for (int c = 0; c < 3; ++c)
        exact[c] = glm::dvec4(r[c] * scale, 0.0);
    return exact;
}

Json point(const glm::dvec3& p) {
    return Json::array({p.x, p.y, p.z});
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

bool transmits(const Json& material) {
    const std::string type = material.value("type", "");
    if (type == "dielectric" || type == "thin_dielectric" || type == "diffuse_transmission")
        return true;
    if (type == "mix") return transmits(material["a"]) || transmits(material["b"]);
    return false;
}

// An object holding `shape` alone (in its own space), and the instance placing it by `m`.
Json placedByInstance(TranslationContext& ctx, Json shape, const glm::dmat4& m) {
    const auto taken = [&](const std::string& name) {
        if (ctx.document.contains("objects") && ctx.document["objects"].contains(name)) return true;
        return std::any_of(ctx.scene.objects.begin(), ctx.scene.objects.end(),
                           [&](const ObjectDef& o) { return o.name == name; });
    };
    const std::string type = shape["type"];
    std::string name;
    for (int i = 1; name.empty() || taken(name); ++i)
        name = "placed " + type + " " + std::to_string(i);
    Json instance{{"type", "instance"},
                  {"object", name},
                  {"transform", Json::array({Json{{"matrix", rowMajor(m)}}})}};
    if (shape.contains("name")) instance["name"] = shape["name"];
    ctx.document["objects"][name] = Json::array({std::move(shape)});
    return instance;
}

}  // namespace

Json rowMajor(const glm::dmat4& m) {
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            rows.push_back(m[c][r]);
    return rows;
}

std::optional<Json> translateShape(TranslationContext& ctx, const ShapeDef& s, bool inObject) {
    const Entity& e = s.entity;
    const ParamList& params = e.params;
    const glm::dmat4& m = e.transform;
    const std::string material = useMaterial(ctx, s.material, s.materialLocation);
    // pbrt-v4 gives a shape a MediumInterface only where the two sides differ (scene.cpp);
    // elsewhere the shape leaves the medium a path is in alone, as a lamina shape without
    // "interior" and "exterior" does.
    const bool boundary = s.media.isTransition();
    if (material.empty() && !boundary) {
        ctx.warn(e.location, "Shape \"" + e.type +
                                 "\" with the \"interface\" material separates no media: "
                                 "omitted (pbrt-v4's rays pass through it)");
        return std::nullopt;
    }
    if (material.empty() && s.areaLight)
        ctx.fail(e.location, "an emitting Shape \"" + e.type +
                                 "\" with the \"interface\" material is not supported "
                                 "(give the emitter a material)");
    // An interface (the lamina material "interface") has no material entry: transmits().
    const Json interfaceMaterial{{"type", "dielectric"}};
    const Json& materialJson =
        material.empty() ? interfaceMaterial : ctx.document["materials"][material];
    Json shape;
    std::vector<double> areas;  // for an area light's power
    // A quadric under a shear or an uneven scale (an ellipsoid, an elliptic cylinder or disk)
    // is exact as an object of the quadric in its own space, placed by an instance with the
    // transform (lamina's instances take any invertible transform, docs/scene-format.md).
    bool viaInstance = false;
    auto similarity = [&]() {
        double rounded = 0;
        const double scale = similarityScale(m, rounded);
        if (scale == 0) {
            if (s.areaLight || inObject)
                ctx.fail(e.location,
                         "Shape \"" + e.type + "\" under a shear or an uneven scale is not " +
                             (s.areaLight ? "supported when it emits (lamina places it as an "
                                            "instance, and instances cannot emit)"
                                          : "supported inside ObjectBegin or on a moving "
                                            "shape (lamina places it as an instance, and "
                                            "instances do not nest)"));
            viaInstance = true;
            return 1.0;
        }
        if (rounded > 1e-9)
            ctx.warn(e.location,
                     "Shape \"" + e.type +
                         "\": its transform is a rotation and uniform scale to within " +
                         deviationText(rounded) +
                         " (rounded digits): the shape stays round, of the mean scale");
        return scale;
    };
    // pbrt-v4's clipped quadrics (their constructors in shapes.h, their parameters in
    // shapes.cpp) become lamina's in their own frame, placed by the transform (its rotation
    // made exact); a clipping that leaves no area omits the shape (noArea), as pbrt-v4 renders
    // nothing of it.
    bool ownTransform = false, noArea = false;
    // Places the shape at m * local: as an exact similarity, or in the instance's own space.
    const auto place = [&](const glm::dmat4& local, double scale) {
        ownTransform = true;
        const glm::dmat4 exact = viaInstance ? local : exactSimilarity(m * local, scale);
        if (!isIdentity(exact))
            shape["transform"] = Json::array({Json{{"matrix", rowMajor(exact)}}});
    };
    const auto phiMaxParam = [&]() {
        return std::clamp(params.number("phimax", 360.0), 0.0, 360.0);
    };
    const auto positiveRadius = [&](double r) {
        if (!(r > 0)) ctx.fail(e.location, "Shape \"" + e.type + "\": \"radius\" must be > 0");
    };
    if (e.type == "sphere") {
        const double r = params.number("radius", 1.0);
        // z_min and z_max in either order, clamped to the sphere; phi_max to [0, 360].
        const double z0 = params.number("zmin", -r), z1 = params.number("zmax", r);
        const double phiMax = phiMaxParam();
        const double zMin = std::clamp(std::min(z0, z1), -std::abs(r), std::abs(r));
        const double zMax = std::clamp(std::max(z0, z1), -std::abs(r), std::abs(r));
        if (zMin > -r || zMax < r || phiMax < 360) {
            positiveRadius(r);
            const double scale = similarity();
            shape = {{"type", "sphere"}, {"radius", r}};
            place(glm::dmat4(1.0), scale);
            if (zMin > -r) shape["z_min"] = zMin;
            if (zMax < r) shape["z_max"] = zMax;
            if (phiMax < 360) shape["phi_max"] = phiMax;
            noArea = !(zMax > zMin) || !(phiMax > 0);
            areas = {phiMax * kPi / 180 * r * (zMax - zMin) * scale * scale};
        } else {
            const double radius = r * similarity();
            shape = {{"type", "sphere"},
                     {"center", point(viaInstance ? glm::dvec3(0.0) : apply(m, glm::dvec3(0.0)))},
                     {"radius", radius}};
            ownTransform = viaInstance;
            areas = {4 * kPi * radius * radius};
        }
        // pbrt's sphere faces outwards whatever the transform's handedness; ReverseOrientation
        // turns it inwards.
        if (s.reverseOrientation) shape["flip_normals"] = true;
    } else if (e.type == "cylinder") {
        // Open (no caps), about z; z_min and z_max in either order.
        const double r = params.number("radius", 1.0);
        const double z0 = params.number("zmin", -1.0), z1 = params.number("zmax", 1.0);
        const double phiMax = phiMaxParam();
        positiveRadius(r);
        const double scale = similarity();
        const double zMin = std::min(z0, z1), zMax = std::max(z0, z1);
        shape = {{"type", "cylinder"}, {"radius", r}, {"z_min", zMin}, {"z_max", zMax}};
        place(glm::dmat4(1.0), scale);
        if (phiMax < 360) shape["phi_max"] = phiMax;
        // Outwards, as the sphere.
        if (s.reverseOrientation) shape["flip_normals"] = true;
        noArea = !(zMax > zMin) || !(phiMax > 0);
        areas = {phiMax * kPi / 180 * r * (zMax - zMin) * scale * scale};
    } else if (e.type == "disk") {
        const double r = params.number("radius", 1.0), h = params.number("height", 0.0);
        const double innerRadius = params.number("innerradius", 0.0);
        const double phiMax = phiMaxParam();
        // The disk faces its object space's +z, transformed as a normal (shapes.h, Disk).
        const bool mirrors = glm::determinant(glm::dmat3(m)) < 0;
        if (innerRadius != 0 || phiMax < 360) {
            positiveRadius(r);
            if (innerRadius < 0)
                ctx.fail(e.location, "Shape \"disk\": \"innerradius\" must be >= 0");
            const double scale = similarity();
            shape = {{"type", "disk"}, {"radius", r}};
            place(glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0),
                             glm::dvec4(0, 0, h, 1)),
                  scale);
            if (innerRadius > 0) shape["inner_radius"] = innerRadius;
            if (phiMax < 360) shape["phi_max"] = phiMax;
            // A lamina disk turns its front over under a mirroring transform; pbrt-v4's
            // (above) does not.
            if (s.reverseOrientation != mirrors) shape["flip_normals"] = true;
            noArea = !(innerRadius < r) || !(phiMax > 0);
            areas = {phiMax * kPi / 360 * (r - innerRadius) * (r + innerRadius) * scale * scale};
        } else {
            const double radius = r * similarity();
            const glm::dmat4 to = viaInstance ? glm::dmat4(1.0) : m;
            ownTransform = viaInstance;
            glm::dvec3 n = glm::transpose(glm::inverse(glm::dmat3(to))) * glm::dvec3(0, 0, 1);
            // An instance turns a disk's front over under a mirroring transform (geometry.cpp),
            // which pbrt-v4's does not: the object's disk faces the other way then.
            const bool turned = s.reverseOrientation != (viaInstance && mirrors);
            n = glm::normalize(n) * (turned ? -1.0 : 1.0);
            shape = {{"type", "disk"},
                     {"center", point(apply(to, glm::dvec3(0, 0, h)))},
                     {"normal", point(n)},
                     {"radius", radius}};
            areas = {kPi * radius * radius};
        }
    } else if (e.type == "trianglemesh" || e.type == "bilinearmesh") {
        const bool bilinear = e.type == "bilinearmesh";
        const Mesh mesh = readMesh(e, bilinear ? 4 : 3);
        if (params.has("S")) {
            params.numbers("S", {"vector3"}, 3);
            ctx.warn(e.location,
                     "the per-vertex tangents \"S\" ignored: lamina builds the "
                     "tangent frame from the normal");
        }
        if (params.has("faceIndices")) {
            params.find("faceIndices");
            ctx.warn(e.location, "\"faceIndices\" ignored: they only seed pbrt's ptex lookups");
        }
        if (bilinear && !planar(mesh))
            ctx.warn(e.location, "bilinearmesh: a non-planar patch became two triangles");
        shape = meshJson(mesh, s.reverseOrientation);
        areas = faceAreas(mesh, m);
    } else if (e.type == "loopsubdiv") {
        const Mesh mesh = subdividedMesh(ctx, e);
        shape = meshJson(mesh, s.reverseOrientation);
        areas = faceAreas(mesh, m);
    } else if (e.type == "curve") {
        if (s.areaLight)
            ctx.fail(e.location,
                     "an emitting Shape \"curve\" is not supported (lamina's "
                     "curves do not emit)");
        shape = curveShape(ctx, e);
    } else if (e.type == "plymesh") {
        const Param* file = params.find("filename");
        if (!file) ctx.fail(e.location, "plymesh: no \"string filename\" parameter");
        params.expectType(*file, {"string"});
        shape = {{"type", "ply"}, {"file", ctx.filePath(params, *file)}};
        if (s.reverseOrientation) {
            if (s.areaLight || transmits(materialJson))
                ctx.fail(e.location,
                         "ReverseOrientation on a plymesh that emits or transmits "
                         "light is not supported (lamina cannot turn a PLY file's "
                         "winding around)");
            ctx.warn(e.location,
                     "ReverseOrientation on an opaque plymesh ignored: it changes "
                     "nothing there");
        }
    } else {
        ctx.fail(e.location, "Shape \"" + e.type +
                                 "\" is not supported (lamina reads sphere, "
                                 "disk, cylinder, trianglemesh, plymesh, bilinearmesh, "
                                 "loopsubdiv and curve)");
    }
    shape["material"] = material.empty() ? kDocumentInterfaceMaterial : material;
    if (boundary) {
        shape["interior"] = useMedium(ctx, s.media.inside, s.media.location);
        shape["exterior"] = useMedium(ctx, s.media.outside, s.media.location);
    }
    if (const auto sub = ctx.subsurfaceInteriors.find(s.material);
        sub != ctx.subsurfaceInteriors.end()) {
        // A subsurface material's shape holds its medium (pbrt_materials.cpp).
        if (boundary && !s.media.inside.empty())
            ctx.warn(e.location, "the subsurface material's medium replaces the interior \"" +
                                     s.media.inside + "\" of the MediumInterface");
        shape["interior"] = sub->second;
    }
    if (!shape.contains("center") && !ownTransform && !isIdentity(m))
        shape["transform"] = Json::array({Json{{"matrix", rowMajor(m)}}});
    // Alpha cut-outs ("float alpha" or a float texture; pbrt-v4 shapes.cpp).
    if (const Param* alpha = params.find("alpha")) {
        params.expectType(*alpha, {"float", "texture"});
        if (s.areaLight) {
            // pbrt-v4 emits only where its stochastic alpha test keeps the surface
            // (DiffuseAreaLight::AlphaMasked, lights.h): everywhere for alpha 1, nowhere for 0.
            const bool constant = canonicalParamType(alpha->type) == "float";
            const double a = constant ? params.number("alpha", 1.0) : 0.5;
            if (a > 0 && a < 1)  // 0 and 1 are taken below
                ctx.fail(alpha->location, "alpha on an emitting shape is not supported");
            if (a <= 0) {
                ctx.warn(alpha->location,
                         "an emitting Shape \"" + e.type +
                             "\" of alpha 0 omitted: pbrt-v4 neither sees it nor lets it emit");
                areaEmission(ctx, *s.areaLight, areas);  // its parameters are still checked
                params.refuseUnused();
                return std::nullopt;
            }
        }
        if (canonicalParamType(alpha->type) == "texture")
            shape["alpha"] = {
                {"texture", useTexture(ctx, alpha->strings.at(0), "float", alpha->location)}};
        else if (params.number("alpha", 1.0) < 1)
            shape["alpha"] = std::max(0.0, params.number("alpha", 1.0));
    }
    if (s.areaLight) shape["emission"] = areaEmission(ctx, *s.areaLight, areas);
    params.refuseUnused();
    if (noArea) {
        ctx.warn(e.location, "Shape \"" + e.type +
                                 "\" omitted: its zmin, zmax, phimax or innerradius leave it no "
                                 "area, and pbrt-v4 renders nothing of it");
        return std::nullopt;
    }
    if (viaInstance) return placedByInstance(ctx, std::move(shape), m);
    return shape;
}

Json areaEmission(TranslationContext& ctx, const Entity& light, const std::vector<double>& areas) {
    const ParamList& params = light.params;
    if (light.type != "diffuse")
        ctx.fail(light.location, "AreaLightSource \"" + light.type +
                                     "\" is not supported (lamina reads \"diffuse\")");
    if (params.has("filename"))
        ctx.fail(light.location,
                 "AreaLightSource \"diffuse\": an emission image (filename) is "
                 "not supported");
    const bool twoSided = params.boolean("twosided", false);
    double scale = params.number("scale", 1.0);
    const double power = params.number("power", -1.0);
    if (power > 0) {
        // pbrt-v4 (DiffuseAreaLight::Create): scale *= power / (pi (2 if two-sided) area),
        // per shape: every triangle of a mesh is a shape of its own that emits `power`.
        if (areas.empty())
            ctx.fail(light.location,
                     "\"power\" on a plymesh is not supported (its area is not "
                     "known before the file is read)");
        for (double a : areas)
            if (std::abs(a - areas[0]) > 1e-6 * areas[0])
                ctx.fail(light.location,
                         "\"power\" on a mesh whose triangles differ in area "
                         "is not supported (pbrt gives each triangle that "
                         "power, so their radiances differ)");
        if (!(areas[0] > 0)) ctx.fail(light.location, "\"power\" on a shape of zero area");
        scale *= power / (kPi * (twoSided ? 2 : 1) * areas[0]);
        if (areas.size() > 1)
            ctx.warn(light.location, "\"power\" applies to each of the mesh's " +
                                         std::to_string(areas.size()) +
                                         " triangles, as in pbrt-v4: the mesh emits " +
                                         std::to_string(areas.size()) + " times that power");
    }
    Json emission{{"radiance", emissionValue(ctx, params, "L", scale)}};
    if (twoSided) emission["two_sided"] = true;
    params.refuseUnused();
    return emission;
}

}  // namespace lamina::render::pbrt
