#include "surface_derivatives.h"

#include <cmath>

#include "lamina/geometry/quadric.h"

namespace lamina::render {

SurfaceDerivatives surfaceDerivatives(const MeshDesc& m, std::uint32_t triangle, float b1, float b2,
                                      const SurfaceHit& hit) {
    SurfaceDerivatives d;
    const auto& tri = m.triangles[triangle];
    Vec2f uv[3] = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(0, 1)};  // hit.uv = (b1, b2) without uvs
    if (!m.uvs.empty())
        for (int k = 0; k < 3; ++k)
            uv[k] = m.uvs[tri[std::size_t(k)]];
    const Vec2f duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
    const float determinant = duv02.x * duv12.y - duv02.y * duv12.x;
    const float inverse = 1.0f / determinant;
    if (determinant == 0.0f || !std::isfinite(inverse)) return d;  // degenerate uvs
    // p - p2 = du02 (u - u2) ... solved for dp/du and dp/dv (the 2 x 2 system's inverse).
    const auto derivative = [&](const Vec3f& d02, const Vec3f& d12, Vec3f& du, Vec3f& dv) {
        du = (duv12.y * d02 - duv02.y * d12) * inverse;
        dv = (duv02.x * d12 - duv12.x * d02) * inverse;
    };
    const Vec3f& p2 = m.positions[tri[2]];
    derivative(m.positions[tri[0]] - p2, m.positions[tri[1]] - p2, d.dpdu, d.dpdv);
    if (!m.normals.empty()) {
        const Vec3f& n0 = m.normals[tri[0]];
        const Vec3f& n1 = m.normals[tri[1]];
        const Vec3f& n2 = m.normals[tri[2]];
        derivative(n0 - n2, n1 - n2, d.dndu, d.dndv);
        // The shading normal was turned to the geometric side: so are its derivatives.
        const Vec3f n = (1.0f - b1 - b2) * n0 + b1 * n1 + b2 * n2;
        if (glm::dot(n, hit.ng) < 0) {
            d.dndu = -d.dndu;
            d.dndv = -d.dndv;
        }
    }
    return d;
}

SurfaceDerivatives surfaceDerivatives(const SphereDesc& s, const SurfaceHit& hit) {
    SurfaceDerivatives d;
    const Vec3<double> q = Vec3<double>(hit.p) - s.center;
    const double sinTheta = std::sqrt(q.x * q.x + q.y * q.y) / s.radius;
    if (!(sinTheta > 0)) return d;  // a pole: u is undefined there
    const double cosTheta = q.z / s.radius;
    const double cosPhi = q.x / (s.radius * sinTheta), sinPhi = q.y / (s.radius * sinTheta);
    const Vec3<double> dpdu = 2 * kPi<double> * Vec3<double>(-q.y, q.x, 0);
    const Vec3<double> dpdv =
        kPi<double> * s.radius * Vec3<double>(cosTheta * cosPhi, cosTheta * sinPhi, -sinTheta);
    d.dpdu = Vec3f(dpdu);
    d.dpdv = Vec3f(dpdv);
    const double sign = s.flipNormals ? -1.0 : 1.0;
    d.dndu = Vec3f(sign * dpdu / s.radius);
    d.dndv = Vec3f(sign * dpdv / s.radius);
    return d;
}

SurfaceDerivatives surfaceDerivatives(const DiskDesc& dk, const SurfaceHit& hit) {
    SurfaceDerivatives d;
    const Frame<double> frame = Frame<double>::fromNormal(dk.normal);
    const Vec3<double> local = frame.toLocal(Vec3<double>(hit.p) - dk.center);
    const double rho = std::sqrt(local.x * local.x + local.y * local.y);
    if (!(rho > 0)) return d;  // the centre: v is undefined there
    d.dpdu = Vec3f(dk.radius / rho * (local.x * frame.s + local.y * frame.t));
    d.dpdv = Vec3f(2 * kPi<double> * (-local.y * frame.s + local.x * frame.t));
    return d;
}

SurfaceDerivatives surfaceDerivatives(const QuadricDesc& q, const SurfaceHit& hit) {
    const QuadricSurface s = quadricSurface(q, q.toLocal(Vec3<double>(hit.p)));
    SurfaceDerivatives d;
    d.dpdu = Vec3f(s.dpdu);
    d.dpdv = Vec3f(s.dpdv);
    d.dndu = Vec3f(s.dndu);
    d.dndv = Vec3f(s.dndv);
    return d;
}

}  // namespace lamina::render
