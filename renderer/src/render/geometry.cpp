#include "lamina/render/geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lamina::render {

Geometry::Geometry(const SceneDesc& scene) : scene_(scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("cannot create an Embree device");
    scene3_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene3_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene3_, RTC_BUILD_QUALITY_HIGH);

    Vec3<double> lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const MeshDesc& m = scene.meshes[i];
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              m.positions.size()));
        for (std::size_t k = 0; k < m.positions.size(); ++k) {
            for (int c = 0; c < 3; ++c)
                v[3 * k + std::size_t(c)] = m.positions[k][c];
            lo = glm::min(lo, Vec3<double>(m.positions[k]));
            hi = glm::max(hi, Vec3<double>(m.positions[k]));
        }
        auto* idx = static_cast<std::uint32_t*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(std::uint32_t), m.triangles.size()));
        for (std::size_t k = 0; k < m.triangles.size(); ++k)
            for (int c = 0; c < 3; ++c)
                idx[3 * k + std::size_t(c)] = m.triangles[k][std::size_t(c)];
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene3_, g, unsigned(shapes_.size()));
        rtcReleaseGeometry(g);
        shapes_.push_back({ShapeInfo::Kind::Mesh, int(i), m.material});
    }
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const SphereDesc& s = scene.spheres[i];
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        v[0] = float(s.center.x);
        v[1] = float(s.center.y);
        v[2] = float(s.center.z);
        v[3] = float(s.radius);
        lo = glm::min(lo, s.center - Vec3<double>(s.radius));
        hi = glm::max(hi, s.center + Vec3<double>(s.radius));
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene3_, g, unsigned(shapes_.size()));
        rtcReleaseGeometry(g);
        shapes_.push_back({ShapeInfo::Kind::Sphere, int(i), s.material});
    }
    for (std::size_t i = 0; i < scene.disks.size(); ++i) {
        // Embree's normal-oriented disc points are exact disks.
        const DiskDesc& d = scene.disks[i];
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        v[0] = float(d.center.x);
        v[1] = float(d.center.y);
        v[2] = float(d.center.z);
        v[3] = float(d.radius);
        auto* n = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 1));
        n[0] = float(d.normal.x);
        n[1] = float(d.normal.y);
        n[2] = float(d.normal.z);
        lo = glm::min(lo, d.center - Vec3<double>(d.radius));
        hi = glm::max(hi, d.center + Vec3<double>(d.radius));
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene3_, g, unsigned(shapes_.size()));
        rtcReleaseGeometry(g);
        shapes_.push_back({ShapeInfo::Kind::Disk, int(i), d.material});
    }
    rtcCommitScene(scene3_);
    if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the scene (error code " +
                                 std::to_string(int(e)) + ")");
    if (!shapes_.empty()) {
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

Geometry::~Geometry() {
    if (scene3_) rtcReleaseScene(scene3_);
    if (device_) rtcReleaseDevice(device_);
}

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
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene3_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    SurfaceHit hit;
    hit.t = rh.ray.tfar;
    hit.shape = int(rh.hit.geomID);
    hit.primitive = rh.hit.primID;
    const ShapeInfo& info = shapes_[rh.hit.geomID];
    if (info.kind == ShapeInfo::Kind::Mesh) {
        const MeshDesc& m = scene_.meshes[std::size_t(info.index)];
        const auto& tri = m.triangles[rh.hit.primID];
        const float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
        const Vec3f& p0 = m.positions[tri[0]];
        const Vec3f& p1 = m.positions[tri[1]];
        const Vec3f& p2 = m.positions[tri[2]];
        // Barycentric interpolation is accurate to a few ULPs of the vertices, unlike o + t d.
        hit.p = b0 * p0 + b1 * p1 + b2 * p2;
        hit.ng = normalizeAnyScale(glm::cross(p1 - p0, p2 - p0));
        hit.ns = hit.ng;
        if (!m.normals.empty()) {
            const Vec3f n = safeNormalize(b0 * m.normals[tri[0]] + b1 * m.normals[tri[1]] +
                                          b2 * m.normals[tri[2]]);
            if (n != Vec3f(0.0f)) hit.ns = glm::dot(n, hit.ng) < 0 ? -n : n;
        }
        if (!m.uvs.empty())
            hit.uv = b0 * m.uvs[tri[0]] + b1 * m.uvs[tri[1]] + b2 * m.uvs[tri[2]];
        else
            hit.uv = Vec2f(b1, b2);
    } else if (info.kind == ShapeInfo::Kind::Disk) {
        const DiskDesc& dk = scene_.disks[std::size_t(info.index)];
        // Project o + t d onto the disk's plane (removes the error along the normal).
        const Vec3<double> n = dk.normal;
        Vec3<double> p = Vec3<double>(origin) + double(hit.t) * Vec3<double>(direction);
        p -= glm::dot(p - dk.center, n) * n;
        hit.p = Vec3f(p);
        hit.ng = hit.ns = Vec3f(n);
        const Frame<double> frame = Frame<double>::fromNormal(n);
        const Vec3<double> local = frame.toLocal(p - dk.center);
        hit.uv = Vec2f(float(glm::length(Vec2<double>(local.x, local.y)) / dk.radius),
                       float(std::atan2(local.y, local.x) / (2 * kPi<double>)+0.5));
    } else {
        const SphereDesc& s = scene_.spheres[std::size_t(info.index)];
        const Vec3<double> c = s.center;
        const Vec3<double> p = Vec3<double>(origin) + double(hit.t) * Vec3<double>(direction);
        Vec3<double> n = glm::normalize(p - c);
        // Reproject onto the sphere (pbrt-v4's refinement): the error is then ~1 ULP.
        hit.p = Vec3f(c + s.radius * n);
        hit.uv = Vec2f(float(std::atan2(n.y, n.x) / (2 * kPi<double>)+0.5),
                       float(std::acos(std::clamp(n.z, -1.0, 1.0)) / kPi<double>));
        if (s.flipNormals) n = -n;
        hit.ng = hit.ns = Vec3f(n);
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
    rtcOccluded1(scene3_, &context, &ray);
    return ray.tfar < 0.0f;
}

}  // namespace lamina::render
