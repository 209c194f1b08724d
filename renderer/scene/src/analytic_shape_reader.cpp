// The analytic shapes of "shapes": spheres, disks and cylinders. A whole sphere or disk is a
// SphereDesc or DiskDesc (Embree's own primitives); a sphere or disk clipped as pbrt-v4's are
// (z_min, z_max, phi_max; inner_radius, phi_max) and every cylinder is a QuadricDesc. They
// take similarity transforms only, so that they stay round.
#include <algorithm>

#include "lamina/core/frame.h"
#include "shape_readers.h"

namespace lamina::render {

namespace {

// An analytic shape's transform: a rotation (or a mirroring), a uniform scale and a
// translation. Returns the scale; fails at "transform" for anything else (a shear with equal
// column lengths too: its columns must be orthogonal).
double similarityScale(const JsonReader& r, const Mat4& m, const std::string& what) {
    const glm::dmat3 a(m);
    const double sx = glm::length(a[0]), sy = glm::length(a[1]), sz = glm::length(a[2]);
    const double skew = std::max({std::abs(glm::dot(a[0], a[1])), std::abs(glm::dot(a[0], a[2])),
                                  std::abs(glm::dot(a[1], a[2]))});
    if (!(sx > 0) || !std::isfinite(sx) || std::abs(sx - sy) > 1e-9 * sx ||
        std::abs(sx - sz) > 1e-9 * sx || skew > 1e-9 * sx * sx)
        r.failAt("transform", what + " takes translate, rotate and uniform scale only");
    return sx;
}

// "phi_max" in degrees, (0, 360], in radians (360 exactly 2 pi: the shape is not clipped).
double readPhiMax(const JsonReader& r) {
    const double degrees = r.number("phi_max", 360.0, Range{0.0, 360.0, true, false});
    return degrees == 360 ? 2 * kPi<double> : radians(degrees);
}

// What every quadric checks once placed: its box within float range, an emitter's area.
void finishQuadric(const JsonReader& r, const QuadricDesc& q, const std::string& what) {
    Vec3d lo, hi;
    q.bounds(lo, hi);
    checkCoordinates(r,
                     r.has("transform") ? "transform"
                     : r.has("center")  ? "center"
                                        : "radius",
                     glm::max(glm::abs(lo), glm::abs(hi)), what + "'s bounding box corner");
    if (q.emission) checkEmitterArea(r, q.area());
}

// The surface keys of a shape (material, emission, alpha), read into `s`.
void readSurface(const JsonReader& r, SurfaceDesc& s, const std::string& name,
                 SceneMaterials& materials, const std::string& what) {
    s.name = name;
    s.material = materials.materialOf(r);
    s.emission = readEmission(r);
    s.alpha = readAlpha(r, materials);
    if (s.alpha.texture >= 0)
        r.failAt("alpha",
                 "a texture alpha is read at a triangle shape's uv; " + what + " takes a number");
}

}  // namespace

ShapeDesc readSphere(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    const Vec3d center = readVec3(r, "center", Vec3d(0.0));
    const double radius = r.number("radius", 1.0, Range::positive());
    const bool flip = r.boolean("flip_normals", false);
    // pbrt-v4's clipping (Sphere::Create): z_min and z_max in the sphere's own frame.
    const double zMin = r.number("z_min", -radius, Range{-radius, radius});
    const double zMax = r.number("z_max", radius, Range{-radius, radius});
    if (!(zMax > zMin))
        r.failAt("z_max", "expected more than z_min (" + formatNumber(zMin) +
                              "): the sphere would have no area");
    const double phiMax = readPhiMax(r);
    SphereDesc s;
    readSurface(r, s, name, materials, "a sphere");
    s.flipNormals = flip;
    const Mat4 m = readTransform(r);
    const double scale = similarityScale(r, m, "a sphere");
    if (zMin == -radius && zMax == radius && phiMax == 2 * kPi<double>) {
        s.center = Vec3d(m * glm::dvec4(center, 1.0));
        s.radius = radius * scale;
        checkCoordinates(r, "center", glm::abs(s.center) + s.radius,
                         "the sphere's bounding box corner");
        if (s.emission) checkEmitterArea(r, 4.0 * kPi<double> * s.radius * s.radius);
        r.finish();
        return s;
    }
    QuadricDesc q;
    static_cast<SurfaceDesc&>(q) = s;
    q.kind = Quadric::Sphere;
    q.origin = Vec3d(m * glm::dvec4(center, 1.0));
    q.axes = glm::dmat3(m) / scale;
    q.radius = radius * scale;
    q.zMin = zMin * scale;
    q.zMax = zMax * scale;
    q.phiMax = phiMax;
    // Outwards whatever the transform's handedness, as a whole sphere.
    q.flipNormals = flip;
    finishQuadric(r, q, "the sphere");
    r.finish();
    return q;
}

ShapeDesc readDisk(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    // The unit disk in the plane z = 0 facing +z, or centre / normal / radius.
    const Vec3d center = readVec3(r, "center", Vec3d(0.0));
    Vec3d normal = readVec3(r, "normal", Vec3d(0, 0, 1));
    if (glm::length(normal) == 0) r.failAt("normal", "expected a non-zero vector");
    normal = glm::normalize(normal);
    const double radius = r.number("radius", 1.0, Range::positive());
    const bool flip = r.boolean("flip_normals", false);
    const double innerRadius = r.number("inner_radius", 0.0, Range{0.0, radius, false, true});
    const double phiMax = readPhiMax(r);
    // phi turns from the frame's x axis, which only a transform places: about another normal
    // it would be an axis of lamina's choosing.
    if (phiMax < 2 * kPi<double> && r.has("normal"))
        r.failAt("normal",
                 "a disk with phi_max is oriented by its transform (phi turns from its x axis "
                 "towards its y axis about its +z): leave \"normal\" out and rotate it");
    DiskDesc d;
    readSurface(r, d, name, materials, "a disk");
    const Mat4 m = readTransform(r);
    const double scale = similarityScale(r, m, "a disk");
    const bool mirrors = glm::determinant(glm::dmat3(m)) < 0;
    if (innerRadius == 0 && phiMax == 2 * kPi<double>) {
        d.center = Vec3d(m * glm::dvec4(center, 1.0));
        d.normal =
            glm::normalize(glm::dmat3(m) * normal) * (mirrors ? -1.0 : 1.0) * (flip ? -1.0 : 1.0);
        d.radius = radius * scale;
        checkCoordinates(r, "center", glm::abs(d.center) + d.radius,
                         "the disk's bounding box corner");
        if (d.emission) checkEmitterArea(r, kPi<double> * d.radius * d.radius);
        r.finish();
        return d;
    }
    QuadricDesc q;
    static_cast<SurfaceDesc&>(q) = d;
    q.kind = Quadric::Disk;
    // About a given normal the frame is the whole disk's (Frame::fromNormal): only an annulus
    // (phi_max 360) gets here with one.
    const Frame<double> frame = Frame<double>::fromNormal(normal);
    q.origin = Vec3d(m * glm::dvec4(center, 1.0));
    q.axes = glm::dmat3(m) / scale * glm::dmat3(frame.s, frame.t, frame.n);
    q.radius = radius * scale;
    q.innerRadius = innerRadius * scale;
    q.phiMax = phiMax;
    // A mirroring transform turns the disk's front as it turns a whole disk's (above).
    q.flipNormals = flip != mirrors;
    finishQuadric(r, q, "the disk");
    r.finish();
    return q;
}

ShapeDesc readCylinder(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    // pbrt-v4's cylinder (Cylinder::Create): radius 1 about the z axis, z in [-1, 1], open.
    QuadricDesc q;
    q.kind = Quadric::Cylinder;
    const double radius = r.number("radius", 1.0, Range::positive());
    const double zMin = r.number("z_min", -1.0);
    const double zMax = r.number("z_max", 1.0);
    if (!(zMax > zMin))
        r.failAt("z_max", "expected more than z_min (" + formatNumber(zMin) +
                              "): the cylinder would have no area");
    q.phiMax = readPhiMax(r);
    q.flipNormals = r.boolean("flip_normals", false);
    readSurface(r, q, name, materials, "a cylinder");
    const Mat4 m = readTransform(r);
    const double scale = similarityScale(r, m, "a cylinder");
    q.origin = Vec3d(m * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    q.axes = glm::dmat3(m) / scale;
    q.radius = radius * scale;
    q.zMin = zMin * scale;
    q.zMax = zMax * scale;
    finishQuadric(r, q, "the cylinder");
    r.finish();
    return q;
}

}  // namespace lamina::render
