#include "curve_geometry.h"

namespace lamina::render {

namespace {

// The cubic Bezier basis and its derivative at u.
std::array<double, 4> bezierWeights(double u) {
    const double s = 1 - u;
    return {s * s * s, 3 * s * s * u, 3 * s * u * u, u * u * u};
}
std::array<double, 4> bezierDerivativeWeights(double u) {
    const double s = 1 - u;
    return {-3 * s * s, 3 * s * s - 6 * s * u, 6 * s * u - 3 * u * u, 3 * u * u};
}

struct CurvePoint {
    Vec3<double> centre, tangent;  ///< tangent: unit, along increasing u (zero if degenerate)
    double radius;
};

CurvePoint evaluate(const CurvesDesc& c, std::uint32_t segment, double u) {
    const std::uint32_t first = c.segments[segment];
    const auto w = bezierWeights(u), dw = bezierDerivativeWeights(u);
    CurvePoint out{Vec3<double>(0.0), Vec3<double>(0.0), 0.0};
    Vec3<double> derivative(0.0);
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3<double> p(c.points[first + k]);
        out.centre += w[k] * p;
        derivative += dw[k] * p;
        out.radius += w[k] * double(c.radii[first + k]);
    }
    const double len = glm::length(derivative);
    if (len > 0 && std::isfinite(len)) out.tangent = derivative / len;
    return out;
}

}  // namespace

RTCGeometry newCurvesGeometry(RTCDevice device, const CurvesDesc& c) {
    RTCGeometry g =
        rtcNewGeometry(device, c.shape == CurveShape::Flat ? RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE
                                                           : RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), c.points.size()));
    for (std::size_t k = 0; k < c.points.size(); ++k) {
        for (int i = 0; i < 3; ++i)
            v[4 * k + std::size_t(i)] = c.points[k][i];
        v[4 * k + 3] = c.radii[k];
    }
    auto* idx = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(std::uint32_t), c.segments.size()));
    std::copy(c.segments.begin(), c.segments.end(), idx);
    return g;
}

void curveSurfaceAt(const CurvesDesc& c, const Vec3<double>& origin, const Vec3<double>& direction,
                    const RTCHit& h, SurfaceHit& hit) {
    const CurvePoint cp = evaluate(c, h.primID, std::clamp(double(h.u), 0.0, 1.0));
    const Vec3<double> p = origin + double(hit.t) * direction;
    const Vec3<double> t = cp.tangent;
    const Vec3<double> q = p - cp.centre;
    Vec3<double> ng(h.Ng_x, h.Ng_y, h.Ng_z);
    if (c.shape == CurveShape::Cylinder) {
        // The outward normal: from the axis to the point, across the curve. The point is put
        // back on the tube at it (o + t d carries the intersector's error).
        const Vec3<double> across = safeNormalize(Vec3<double>(q - glm::dot(q, t) * t));
        const Vec3<double> n = across != Vec3<double>(0.0) ? across : safeNormalize(ng);
        hit.p = Vec3f(cp.centre + cp.radius * n);
        hit.ng = hit.ns = Vec3f(n);
        hit.uv = Vec2f(h.u, 0.5f);
    } else {
        // The ribbon faces the ray; its shading normal is the tube's at the same offset.
        Vec3<double> face = safeNormalize(Vec3<double>(-direction + glm::dot(direction, t) * t));
        if (face == Vec3<double>(0.0)) face = Frame<double>::fromNormal(t).s;
        Vec3<double> side = q - glm::dot(q, t) * t - glm::dot(q, face) * face;
        side /= std::max(cp.radius, 1e-30);
        const double s2 = std::min(1.0, glm::dot(side, side));
        const Vec3<double> ns = safeNormalize(Vec3<double>(side + std::sqrt(1 - s2) * face));
        hit.p = Vec3f(p);
        hit.ng = Vec3f(face);
        hit.ns = Vec3f(ns != Vec3<double>(0.0) ? ns : face);
        hit.uv = Vec2f(h.u, 0.5f * (h.v + 1.0f));
    }
    hit.tangent = Vec3f(t);
}

}  // namespace lamina::render
