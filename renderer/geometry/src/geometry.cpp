#include "lamina/geometry/geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "curve_geometry.h"
#include "lamina/core/overloaded.h"
#include "lamina/geometry/quadric.h"
#include "lamina/geometry/ray_time.h"
#include "quadric_geometry.h"
#include "surface_derivatives.h"

namespace lamina::render {

namespace {

RTCScene newScene(RTCDevice device) {
    RTCScene s = rtcNewScene(device);
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    return s;
}

// The sample's time (ray_time.h) as Embree's ray time: instances hold their first transform
// before time 0 and their last after time 1, as pbrt-v4's animated transforms do.
float embreeRayTime() {
    return std::clamp(currentRayTime(), 0.0f, 1.0f);
}

void commitScene(RTCDevice device, RTCScene scene) {
    rtcCommitScene(scene);
    if (const RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the scene (error code " +
                                 std::to_string(int(e)) + ")");
}

}  // namespace

Geometry::Geometry(const SceneDesc& scene) : scene_(scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("cannot create an Embree device");
    scene3_ = newScene(device_);
    addShapes(scene3_, scene.shapes, -1);
    sceneShapes_ = unsigned(shapes_.size());
    Vec3<double> lo, hi;
    boundingBox(scene.shapes, lo, hi);
    addInstances(lo, hi);
    commitScene(device_, scene3_);
    if (!shapes_.empty()) {
        boundsLo_ = Vec3f(lo);
        boundsHi_ = Vec3f(hi);
        boundsCenter_ = Vec3f(0.5 * (lo + hi));
        boundsRadius_ = std::max(1e-3f, float(0.5 * glm::length(hi - lo)));
        const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        constexpr double kSmall = 1.0, kLarge = 65536.0;
        if (extent > 0 && extent < kSmall)
            rayOffsetScale_ = float(std::exp2(std::ceil(std::log2(extent / kSmall))));
        else if (extent > kLarge)
            rayOffsetScale_ = float(std::exp2(std::ceil(std::log2(extent / kLarge))));
    }
}

void Geometry::addShapes(RTCScene target, const std::vector<ShapeDesc>& shapes, int object) {
    // Geometry ids within `target` count from 0 in the order of `shapes`; shapes_ follows it.
    unsigned id = 0;
    for (const ShapeDesc& shape : shapes) {
        RTCGeometry g = std::visit([&](const auto& s) { return newGeometry(s, object); }, shape);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(target, g, id++);
        rtcReleaseGeometry(g);
        const int material = surface(shape).material;
        // A scene built in code may have no material textures at all.
        const bool turnsNormal = material >= 0 &&
                                 std::size_t(material) < scene_.materialTextures.size() &&
                                 scene_.materialTextures[std::size_t(material)].perturbsNormal();
        shapes_.push_back({&shape, material, object, turnsNormal});
    }
}

RTCGeometry Geometry::newGeometry(const MeshDesc& m, int object) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.positions.size()));
    for (std::size_t k = 0; k < m.positions.size(); ++k)
        for (int c = 0; c < 3; ++c)
            v[3 * k + std::size_t(c)] = m.positions[k][c];
    auto* idx = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), m.triangles.size()));
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
        for (int c = 0; c < 3; ++c)
            idx[3 * k + std::size_t(c)] = m.triangles[k][std::size_t(c)];
    addAlphaFilter(g, m.alpha, &m);
    counts_.trianglesStored += m.triangles.size();
    if (object < 0) counts_.trianglesReferenced += m.triangles.size();
    return g;
}

RTCGeometry Geometry::newGeometry(const SphereDesc& s, int) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = float(s.center.x);
    v[1] = float(s.center.y);
    v[2] = float(s.center.z);
    v[3] = float(s.radius);
    addAlphaFilter(g, s.alpha, nullptr);
    return g;
}

RTCGeometry Geometry::newGeometry(const DiskDesc& d, int) {
    // Embree's normal-oriented disc points are exact disks.
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = float(d.center.x);
    v[1] = float(d.center.y);
    v[2] = float(d.center.z);
    v[3] = float(d.radius);
    auto* n = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_NORMAL, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float), 1));
    n[0] = float(d.normal.x);
    n[1] = float(d.normal.y);
    n[2] = float(d.normal.z);
    addAlphaFilter(g, d.alpha, nullptr);
    return g;
}

RTCGeometry Geometry::newGeometry(const QuadricDesc& q, int) {
    // A cut-out is tested in the user geometry's own callbacks (quadric_geometry.h).
    quadrics_.push_back(std::make_unique<QuadricGeometry>(QuadricGeometry{&q, q.alpha.value}));
    return newQuadricGeometry(device_, *quadrics_.back());
}

RTCGeometry Geometry::newGeometry(const CurvesDesc& c, int) {
    RTCGeometry g = newCurvesGeometry(device_, c);
    addAlphaFilter(g, c.alpha, nullptr);
    return g;
}

void Geometry::addAlphaFilter(RTCGeometry g, const AlphaDesc& alpha, const MeshDesc* mesh) {
    if (!alpha.cutsOut()) return;
    auto test = std::make_unique<AlphaTest>();
    test->value = alpha.value;
    if (alpha.texture >= 0) test->texture = scene_.textures[std::size_t(alpha.texture)].get();
    test->mesh = mesh;
    rtcSetGeometryUserData(g, test.get());
    rtcSetGeometryIntersectFilterFunction(g, alphaFilter);
    rtcSetGeometryOccludedFilterFunction(g, alphaFilter);
    alphaTests_.push_back(std::move(test));
}

void Geometry::addInstances(Vec3<double>& lo, Vec3<double>& hi) {
    // Each placed object is one Embree scene, built once, whatever the number of instances.
    objectScenes_.assign(scene_.objects.size(), nullptr);
    objectFirstShape_.assign(scene_.objects.size(), -1);
    for (const InstanceDesc& inst : scene_.instances) {
        const auto o = std::size_t(inst.object);
        if (objectScenes_[o]) continue;
        const ObjectDesc& object = scene_.objects[o];
        objectFirstShape_[o] = int(shapes_.size());
        objectScenes_[o] = newScene(device_);
        addShapes(objectScenes_[o], object.shapes, int(o));
        commitScene(device_, objectScenes_[o]);
        ++counts_.objectsBuilt;
    }
    std::vector<std::size_t> objectTriangles(scene_.objects.size(), 0);
    for (std::size_t o = 0; o < scene_.objects.size(); ++o)
        for (const ShapeDesc& shape : scene_.objects[o].shapes)
            if (const auto* m = std::get_if<MeshDesc>(&shape))
                objectTriangles[o] += m->triangles.size();
    unsigned id = sceneShapes_;
    for (const InstanceDesc& inst : scene_.instances) {
        const auto o = std::size_t(inst.object);
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, objectScenes_[o]);
        // 3 x 4, column-major: the linear part's columns, then the translation; a moving
        // instance has a second matrix at time 1 (two Embree time steps).
        const auto embreeMatrix = [](const glm::dmat4& m, float* xfm) {
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 3; ++row)
                    xfm[col * 3 + row] = float(m[col][row]);
        };
        float xfm[12], xfmEnd[12];
        embreeMatrix(inst.toWorld, xfm);
        if (inst.toWorldEnd) {
            embreeMatrix(*inst.toWorldEnd, xfmEnd);
            rtcSetGeometryTimeStepCount(g, 2);
            rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
            rtcSetGeometryTransform(g, 1, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfmEnd);
        } else {
            rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene3_, g, id++);
        rtcReleaseGeometry(g);

        // The hit is rebuilt with the transform Embree traced (float), in double.
        InstanceTransform t = InstanceTransform::fromEmbree(xfm);
        if (inst.toWorldEnd) t.toWorldEnd = InstanceTransform::fromEmbree(xfmEnd).toWorld;
        instanceTransforms_.push_back(t);

        // Each corner moves on a straight line between its two ends (the interpolation is
        // linear in the matrix): the box of both ends holds the instance at every time.
        Vec3<double> olo, ohi;
        boundingBox(scene_.objects[o].shapes, olo, ohi);
        for (int corner = 0; corner < 16; ++corner) {
            const Vec3<double> p((corner & 1) ? ohi.x : olo.x, (corner & 2) ? ohi.y : olo.y,
                                 (corner & 4) ? ohi.z : olo.z);
            const glm::dmat4& m = (corner & 8) && t.toWorldEnd ? *t.toWorldEnd : t.toWorld;
            const Vec3<double> w(m * glm::dvec4(p, 1.0));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
        ++counts_.instances;
        counts_.trianglesReferenced += objectTriangles[o];
    }
}

Geometry::~Geometry() {
    if (scene3_) rtcReleaseScene(scene3_);
    for (RTCScene s : objectScenes_)
        if (s) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
}

namespace {

// The surface at a hit of a shape, in the shape's own space (the world, or its object's): one
// function per kind of ShapeDesc.

void surfaceAt(const MeshDesc& m, const Vec3<double>&, const Vec3<double>&, const RTCHit& h,
               SurfaceHit& hit) {
    const auto& tri = m.triangles[h.primID];
    const float b1 = h.u, b2 = h.v, b0 = 1.0f - b1 - b2;
    const Vec3f& p0 = m.positions[tri[0]];
    const Vec3f& p1 = m.positions[tri[1]];
    const Vec3f& p2 = m.positions[tri[2]];
    // Barycentric interpolation is accurate to a few ULPs of the vertices, unlike o + t d.
    hit.p = b0 * p0 + b1 * p1 + b2 * p2;
    hit.ng = normalizeAnyScale(glm::cross(p1 - p0, p2 - p0));
    hit.ns = hit.ng;
    if (!m.normals.empty()) {
        const Vec3f n =
            safeNormalize(b0 * m.normals[tri[0]] + b1 * m.normals[tri[1]] + b2 * m.normals[tri[2]]);
        if (n != Vec3f(0.0f)) hit.ns = glm::dot(n, hit.ng) < 0 ? -n : n;
    }
    if (!m.uvs.empty())
        hit.uv = b0 * m.uvs[tri[0]] + b1 * m.uvs[tri[1]] + b2 * m.uvs[tri[2]];
    else
        hit.uv = Vec2f(b1, b2);
}

void surfaceAt(const DiskDesc& dk, const Vec3<double>& origin, const Vec3<double>& direction,
               const RTCHit&, SurfaceHit& hit) {
    // Project o + t d onto the disk's plane (removes the error along the normal).
    const Vec3<double> n = dk.normal;
    Vec3<double> p = origin + double(hit.t) * direction;
    p -= glm::dot(p - dk.center, n) * n;
    hit.p = Vec3f(p);
    hit.ng = hit.ns = Vec3f(n);
    const Frame<double> frame = Frame<double>::fromNormal(n);
    const Vec3<double> local = frame.toLocal(p - dk.center);
    hit.uv = Vec2f(float(glm::length(Vec2<double>(local.x, local.y)) / dk.radius),
                   float(std::atan2(local.y, local.x) / (2 * kPi<double>)+0.5));
}

void surfaceAt(const SphereDesc& s, const Vec3<double>& origin, const Vec3<double>& direction,
               const RTCHit&, SurfaceHit& hit) {
    const Vec3<double> c = s.center;
    const Vec3<double> p = origin + double(hit.t) * direction;
    Vec3<double> n = glm::normalize(p - c);
    // Reproject onto the sphere (pbrt-v4's refinement): the error is then ~1 ULP.
    hit.p = Vec3f(c + s.radius * n);
    // In float: uv is stored in float, and libm's double atan2 and acos took 6% of a render
    // whose rays cross a sphere at every step (the boundary of a cloud).
    const Vec3f nf(n);
    hit.uv = Vec2f(std::atan2(nf.y, nf.x) / (2 * kPi<float>)+0.5f,
                   std::acos(std::clamp(nf.z, -1.0f, 1.0f)) / kPi<float>);
    if (s.flipNormals) n = -n;
    hit.ng = hit.ns = Vec3f(n);
}

void surfaceAt(const QuadricDesc& q, const Vec3<double>& origin, const Vec3<double>& direction,
               const RTCHit&, SurfaceHit& hit) {
    // o + t d projected onto the surface, in double (quadricSurface).
    const QuadricSurface s = quadricSurface(q, q.toLocal(origin + double(hit.t) * direction));
    hit.p = Vec3f(s.p);
    hit.ng = hit.ns = Vec3f(s.n);
    hit.uv = Vec2f(s.uv);
}

void surfaceAt(const CurvesDesc& c, const Vec3<double>& origin, const Vec3<double>& direction,
               const RTCHit& h, SurfaceHit& hit) {
    curveSurfaceAt(c, origin, direction, h, hit);
}

// Whether a shape's front is a side of its plane (a disk's), which a mirroring transform
// turns over, rather than its outside.
bool facesOneSideOfAPlane(const ShapeDesc& shape) {
    if (std::holds_alternative<DiskDesc>(shape)) return true;
    const auto* q = std::get_if<QuadricDesc>(&shape);
    return q && q->kind == Quadric::Disk;
}

void surfaceAt(const ShapeInfo& info, const Vec3<double>& origin, const Vec3<double>& direction,
               const RTCHit& h, SurfaceHit& hit) {
    std::visit([&](const auto& shape) { surfaceAt(shape, origin, direction, h, hit); }, *info.desc);
    if (!info.turnsNormal) return;
    hit.derivatives = std::visit(
        Overloaded{
            [&](const MeshDesc& m) { return surfaceDerivatives(m, h.primID, h.u, h.v, hit); },
            [&](const auto& shape) { return surfaceDerivatives(shape, hit); }},
        *info.desc);
}

}  // namespace

std::optional<SurfaceHit> Geometry::intersect(const Vec3f& origin, const Vec3f& direction,
                                              float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = direction.x;
    rh.ray.dir_y = direction.y;
    rh.ray.dir_z = direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = tMax;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.time = embreeRayTime();
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene3_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    SurfaceHit hit;
    hit.t = rh.ray.tfar;
    hit.primitive = rh.hit.primID;
    if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
        hit.shape = int(rh.hit.geomID);
        const ShapeInfo& info = shapes_[rh.hit.geomID];
        surfaceAt(info, Vec3<double>(origin), Vec3<double>(direction), rh.hit, hit);
        if (info.turnsNormal)
            hit.ns = perturbedShadingNormal(scene_, info.material, {hit.uv, hit.p, hit.ng}, hit.ng,
                                            hit.ns, hit.derivatives);
        return hit;
    }
    // An instance's hit: the surface in the object's space along the ray Embree traced there
    // (the same t), then carried to the world. Normals take the inverse transpose, which keeps
    // them on the outside under a mirroring transform, as the winding swap does for shapes
    // (shape_reader.cpp); a disk's front turns as a transformed disk's does.
    hit.instance = int(rh.hit.instID[0] - sceneShapes_);
    // A moving instance's transform at the ray's time, as Embree traced it.
    const InstanceTransform& stored = instanceTransforms_[std::size_t(hit.instance)];
    const std::optional<InstanceTransform> moved =
        stored.toWorldEnd ? std::optional(stored.at(rh.ray.time)) : std::nullopt;
    const InstanceTransform& xf = moved ? *moved : stored;
    const int object = scene_.instances[std::size_t(hit.instance)].object;
    hit.shape = objectFirstShape_[std::size_t(object)] + int(rh.hit.geomID);
    const ShapeInfo& info = shapes_[std::size_t(hit.shape)];
    const Vec3<double> o(xf.toObject * glm::dvec4(Vec3<double>(origin), 1.0));
    const Vec3<double> d(glm::dmat3(xf.toObject) * Vec3<double>(direction));
    surfaceAt(info, o, d, rh.hit, hit);
    hit.p = Vec3f(xf.toWorld * glm::dvec4(Vec3<double>(hit.p), 1.0));
    const double flip = facesOneSideOfAPlane(*info.desc) && xf.mirrors ? -1.0 : 1.0;
    const Vec3<double> ng = flip * glm::normalize(xf.normalMatrix * Vec3<double>(hit.ng));
    const Vec3<double> nsTransformed = xf.normalMatrix * Vec3<double>(hit.ns);
    Vec3<double> ns = glm::normalize(nsTransformed) * flip;
    const double side = glm::dot(ns, ng) < 0 ? -1.0 : 1.0;
    ns *= side;
    hit.ng = Vec3f(ng);
    hit.ns = Vec3f(ns);
    if (hit.tangent != Vec3f(0.0f))
        hit.tangent = Vec3f(safeNormalize(glm::dmat3(xf.toWorld) * Vec3<double>(hit.tangent)));
    if (info.turnsNormal) {
        // Tangents are vectors; the normal's derivatives are those of the transformed,
        // normalised normal: N dn / |N n| without its component along the new normal.
        SurfaceDerivatives& dw = hit.derivatives;
        const glm::dmat3 linear(xf.toWorld);
        dw.dpdu = Vec3f(linear * Vec3<double>(dw.dpdu));
        dw.dpdv = Vec3f(linear * Vec3<double>(dw.dpdv));
        const double scale = flip * side / glm::length(nsTransformed);
        const auto normalDerivative = [&](const Vec3f& dn) {
            const Vec3<double> v = scale * (xf.normalMatrix * Vec3<double>(dn));
            return Vec3f(v - glm::dot(v, ns) * ns);
        };
        dw.dndu = normalDerivative(dw.dndu);
        dw.dndv = normalDerivative(dw.dndv);
        hit.ns = perturbedShadingNormal(scene_, info.material, {hit.uv, hit.p, hit.ng}, hit.ng,
                                        hit.ns, dw);
    }
    return hit;
}

bool Geometry::occluded(const Vec3f& origin, const Vec3f& direction, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = tMax;
    ray.mask = 0xFFFFFFFFu;
    ray.time = embreeRayTime();
    rtcOccluded1(scene3_, &context, &ray);
    return ray.tfar < 0.0f;
}

}  // namespace lamina::render
