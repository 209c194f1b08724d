#include "quadric_geometry.h"

#include <algorithm>
#include <cmath>

#include "lamina/geometry/quadric.h"

namespace lamina::render {

namespace {

void quadricBounds(const RTCBoundsFunctionArguments* args) {
    const auto& g = *static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    Vec3d lo, hi;
    g.shape->bounds(lo, hi);
    // Widened by a little more than float's rounding of the box and of the ray Embree traverses
    // it with, so that every hit the double-precision test finds is within reach.
    const double pad = 1e-6 * (glm::length(hi - lo) + std::max(glm::length(lo), glm::length(hi)));
    RTCBounds& b = *args->bounds_o;
    b.lower_x = float(lo.x - pad);
    b.lower_y = float(lo.y - pad);
    b.lower_z = float(lo.z - pad);
    b.upper_x = float(hi.x + pad);
    b.upper_y = float(hi.y + pad);
    b.upper_z = float(hi.z + pad);
}

// The nearest hit in (tnear, tfar) that the alpha test keeps, as the float distance Embree
// stores; 0 when there is none.
float nearestHit(const QuadricGeometry& g, const Vec3<float>& o, const Vec3<float>& d, float tnear,
                 float tfar, unsigned instance, unsigned geometry, unsigned primitive) {
    QuadricHit hits[2];
    const int n = intersectQuadric(*g.shape, Vec3d(o), Vec3d(d), double(tnear), double(tfar), hits);
    for (int k = 0; k < n; ++k) {
        const float t = float(hits[k].t);
        if (!(t > tnear && t < tfar)) continue;  // rounded onto an end of the interval
        if (g.alpha < 1.0f) {
            // The filter of alpha_filter.h: ignored unless alpha reaches the hash.
            const float u =
                g.alpha <= 0.0f ? 1.0f : alphaHash(o, d, instance, geometry, primitive, t);
            if (u > g.alpha) continue;
        }
        return t;
    }
    return 0.0f;
}

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto& g = *static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    const unsigned n = args->N;
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, n);
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        const Vec3<float> o(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i),
                            RTCRayN_org_z(ray, n, i));
        const Vec3<float> d(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i),
                            RTCRayN_dir_z(ray, n, i));
        const unsigned instance = args->context->instID[0];
        const float t = nearestHit(g, o, d, RTCRayN_tnear(ray, n, i), RTCRayN_tfar(ray, n, i),
                                   instance, args->geomID, args->primID);
        if (!(t > 0.0f)) continue;
        RTCRayN_tfar(ray, n, i) = t;
        // Geometry::intersect rebuilds the surface from t (quadricSurface): Ng and uv are
        // not read, but set to something defined.
        RTCHitN_Ng_x(hit, n, i) = 0.0f;
        RTCHitN_Ng_y(hit, n, i) = 0.0f;
        RTCHitN_Ng_z(hit, n, i) = 1.0f;
        RTCHitN_u(hit, n, i) = 0.0f;
        RTCHitN_v(hit, n, i) = 0.0f;
        RTCHitN_primID(hit, n, i) = args->primID;
        RTCHitN_geomID(hit, n, i) = args->geomID;
        RTCHitN_instID(hit, n, i, 0) = instance;
    }
}

void quadricOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto& g = *static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        const Vec3<float> o(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i),
                            RTCRayN_org_z(args->ray, n, i));
        const Vec3<float> d(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i),
                            RTCRayN_dir_z(args->ray, n, i));
        const float t =
            nearestHit(g, o, d, RTCRayN_tnear(args->ray, n, i), RTCRayN_tfar(args->ray, n, i),
                       args->context->instID[0], args->geomID, args->primID);
        // An occluded ray is marked with tfar = -infinity (Embree's convention).
        if (t > 0.0f) RTCRayN_tfar(args->ray, n, i) = -std::numeric_limits<float>::infinity();
    }
}

}  // namespace

RTCGeometry newQuadricGeometry(RTCDevice device, QuadricGeometry& data) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryUserData(g, &data);
    rtcSetGeometryBoundsFunction(g, quadricBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, quadricIntersect);
    rtcSetGeometryOccludedFunction(g, quadricOccluded);
    return g;
}

}  // namespace lamina::render
