// RectangleLight (area_lights.h): a rectangle sampled by solid angle near its plane, by area
// farther.
#include <algorithm>

#include "lamina/core/warp.h"
#include "lamina/lights/area_lights.h"

namespace lamina::render {

RectangleLight::RectangleLight(const MeshDesc& mesh) : AreaLight(*mesh.emission, 0.0) {
    // isRectangle(mesh) holds, so the quad has corners.
    const QuadCorners q = *quadCorners(mesh);
    corner_ = Vec3d(mesh.positions[q[0]]);
    const Vec3d ex = Vec3d(mesh.positions[q[1]]) - corner_,
                ey = Vec3d(mesh.positions[q[3]]) - corner_;
    lx_ = glm::length(ex);
    ly_ = glm::length(ey);
    x_ = ex / lx_;
    y_ = ey / ly_;
    n_ = glm::normalize(glm::cross(ex, ey));
    // The winding of (0, 1, 2) gives the front side, as for the triangles.
    // The first triangle's winding gives the front side, as it does the triangles' own
    // geometric normal (a mirroring transform reverses both, shape_reader.cpp).
    const auto& t = mesh.triangles.front();
    const Vec3d winding = glm::cross(Vec3d(mesh.positions[t[1]]) - Vec3d(mesh.positions[t[0]]),
                                     Vec3d(mesh.positions[t[2]]) - Vec3d(mesh.positions[t[0]]));
    if (glm::dot(winding, n_) < 0) n_ = -n_;
    area_ = lx_ * ly_;
    diagonal2_ = lx_ * lx_ + ly_ * ly_;
    // A float hit point on the rectangle itself lies off its plane by the rounding of its
    // coordinates (a few ulps of their magnitude); 1e-5 of it is a hundred times that.
    const Vec3d far = glm::abs(corner_) + glm::abs(ex) + glm::abs(ey);
    planeTolerance_ = 1e-5 * std::max({far.x, far.y, far.z});
}

std::optional<RectangleLight::QuadCorners> RectangleLight::quadCorners(const MeshDesc& m) {
    if (m.positions.size() != 4 || m.triangles.size() != 2) return std::nullopt;
    const auto& t0 = m.triangles[0];
    const auto& t1 = m.triangles[1];
    auto has = [](const std::array<std::uint32_t, 3>& t, std::uint32_t v) {
        return t[0] == v || t[1] == v || t[2] == v;
    };
    auto distinct = [](const std::array<std::uint32_t, 3>& t) {
        return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
    };
    if (!distinct(t0) || !distinct(t1)) return std::nullopt;
    // Two triangles are one quad when they share one edge, its diagonal: t0 then holds one
    // corner t1 lacks (the apex) and t1 one corner t0 lacks.
    int apex = -1, shared = 0;
    for (int k = 0; k < 3; ++k) {
        if (has(t1, t0[std::size_t(k)]))
            ++shared;
        else
            apex = k;
    }
    if (shared != 2) return std::nullopt;
    std::uint32_t opposite = 0;
    for (const std::uint32_t v : t1)
        if (!has(t0, v)) opposite = v;
    // t0 in its own order from the apex: apex, s1, s2 (the diagonal is s1 - s2). t1 must run
    // along the diagonal the other way, s2 then s1, or the two triangles face opposite sides.
    const std::uint32_t s1 = t0[std::size_t((apex + 1) % 3)], s2 = t0[std::size_t((apex + 2) % 3)];
    bool sameSide = false;
    for (std::size_t k = 0; k < 3; ++k)
        if (t1[k] == s2 && t1[(k + 1) % 3] == s1) sameSide = true;
    if (!sameSide) return std::nullopt;
    // The boundary apex, s1, opposite, s2, from corner 0 towards its lower-numbered neighbour:
    // the fan (0, 1, 2), (0, 2, 3) and that fan mirrored give (0, 1, 2, 3).
    const QuadCorners boundary{t0[std::size_t(apex)], s1, opposite, s2};
    const std::size_t zero =
        std::size_t(std::find(boundary.begin(), boundary.end(), 0u) - boundary.begin());
    const bool forward = boundary[(zero + 1) % 4] < boundary[(zero + 3) % 4];
    QuadCorners q{};
    for (std::size_t k = 0; k < 4; ++k)
        q[k] = boundary[(zero + (forward ? k : 4 - k)) % 4];
    return q;
}

bool RectangleLight::isRectangle(const MeshDesc& m) {
    // Any split of the quad along a diagonal covers it exactly, so the triangles may come in
    // any order and either diagonal (a pbrt-v4 bilinear patch's p00, p10, p01, p11 become
    // (0, 1, 3), (0, 3, 2), pbrt_shapes.cpp); the first triangle's winding gives the front
    // (the constructor).
    const auto q = quadCorners(m);
    if (!q) return false;
    const Vec3d p0(m.positions[(*q)[0]]), ex = Vec3d(m.positions[(*q)[1]]) - p0,
                                          ey = Vec3d(m.positions[(*q)[3]]) - p0;
    const double lx = glm::length(ex), ly = glm::length(ey);
    if (!(lx > 0) || !(ly > 0)) return false;
    // Perpendicular sides, and the fourth corner where the other three put it, to within
    // the rounding of float positions (a relative 1e-6 of the sides).
    const double tolerance = 1e-6 * std::max(lx, ly);
    return std::abs(glm::dot(ex, ey)) <= 1e-6 * lx * ly &&
           glm::length(Vec3d(m.positions[(*q)[2]]) - (p0 + ex + ey)) <= tolerance;
}

double RectangleLight::height(const Vec3d& ref) const {
    return glm::dot(ref - corner_, n_);
}

std::optional<LightSample> RectangleLight::sample(const Vec3f& refF, const Vec2f& u) const {
    const Vec3d ref(refF);
    // Behind a one-sided rectangle every point of it faces away (towards() would say so for
    // each): nothing to compute.
    const double h = height(ref);
    if (!twoSided_ && !(h > 0)) return std::nullopt;
    // A point of the rectangle's own plane (a vertex on the emitter itself) sees none of it.
    // Sampled by solid angle from there, the rounding of its height would put it on one side
    // and aim at the plane steeply: a vertex on the emitter's back side would then take the
    // front's light through the surface (path tracing was 0.2% brighter than BDPT on a
    // reflecting lamp before a wall).
    if (std::abs(h) <= planeTolerance_) return std::nullopt;
    // By area as every flat light is, in single precision, as pdf() then computes it.
    if (!bySolidAngle(h)) return AreaLight::sample(refF, u);
    const Spherical sph = spherical(ref);
    if (!(sph.solidAngle > kMinSolidAngle)) return AreaLight::sample(refF, u);
    // Section 4 of the paper: invert the area of the sub-rectangle left of x_u, then the
    // height along y at that x.
    const double au = double(u.x) * sph.solidAngle + sph.k;
    const double fu = (std::cos(au) * sph.b0 - sph.b1) / std::sin(au);
    double cu = (fu > 0 ? 1.0 : -1.0) / std::sqrt(fu * fu + sph.b0 * sph.b0);
    cu = std::clamp(cu, -1.0, 1.0);
    double xu = -(cu * sph.z0) / std::sqrt(std::max(1e-300, 1.0 - cu * cu));
    xu = std::clamp(xu, sph.x0, sph.x1);
    const double dd = std::sqrt(xu * xu + sph.z0 * sph.z0);
    const double h0 = sph.y0 / std::sqrt(dd * dd + sph.y0 * sph.y0);
    const double h1 = sph.y1 / std::sqrt(dd * dd + sph.y1 * sph.y1);
    const double hv = h0 + double(u.y) * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : sph.y1;
    const Vec3d p = ref + xu * sph.x + yv * sph.y + sph.z0 * sph.z;
    return towards(ref, p, n_, 1.0 / sph.solidAngle);
}

float RectangleLight::pdf(const Vec3f& refF, const SurfaceHit& hit) const {
    const double h = height(Vec3d(refF));
    if (std::abs(h) <= planeTolerance_) return 0.0f;  // as sample(): nothing in its plane
    if (bySolidAngle(h))
        if (const Spherical sph = spherical(Vec3d(refF)); sph.solidAngle > kMinSolidAngle)
            return float(1.0 / sph.solidAngle);
    return AreaLight::pdf(refF, hit);
}

std::optional<LightBounds> RectangleLight::bounds() const {
    if (!(area_ > 0)) return std::nullopt;
    const Vec3d ex = lx_ * x_, ey = ly_ * y_;
    const Vec3d lower =
        glm::min(glm::min(corner_, corner_ + ex), glm::min(corner_ + ey, corner_ + ex + ey));
    const Vec3d upper =
        glm::max(glm::max(corner_, corner_ + ex), glm::max(corner_ + ey, corner_ + ex + ey));
    return flatBounds(Vec3f(lower), Vec3f(upper), Vec3f(n_));
}

AreaLight::AreaPoint RectangleLight::samplePoint(const Vec2f& u) const {
    return {corner_ + double(u.x) * lx_ * x_ + double(u.y) * ly_ * y_, n_};
}

RectangleLight::Spherical RectangleLight::spherical(const Vec3d& ref) const {
    Spherical s;
    s.x = x_;
    s.y = y_;
    s.z = glm::cross(x_, y_);
    const Vec3d d = corner_ - ref;
    s.x0 = glm::dot(d, s.x);
    s.y0 = glm::dot(d, s.y);
    s.z0 = glm::dot(d, s.z);
    if (s.z0 > 0) {
        s.z0 = -s.z0;
        s.z = -s.z;
    }
    if (!(std::abs(s.z0) > 0)) return s;  // in the plane: nothing subtended
    s.x1 = s.x0 + lx_;
    s.y1 = s.y0 + ly_;
    const Vec3d v00(s.x0, s.y0, s.z0), v01(s.x0, s.y1, s.z0), v10(s.x1, s.y0, s.z0),
        v11(s.x1, s.y1, s.z0);
    const Vec3d n0 = glm::normalize(glm::cross(v00, v10));
    const Vec3d n1 = glm::normalize(glm::cross(v10, v11));
    const Vec3d n2 = glm::normalize(glm::cross(v11, v01));
    const Vec3d n3 = glm::normalize(glm::cross(v01, v00));
    const double g0 = std::acos(std::clamp(-glm::dot(n0, n1), -1.0, 1.0));
    const double g1 = std::acos(std::clamp(-glm::dot(n1, n2), -1.0, 1.0));
    const double g2 = std::acos(std::clamp(-glm::dot(n2, n3), -1.0, 1.0));
    const double g3 = std::acos(std::clamp(-glm::dot(n3, n0), -1.0, 1.0));
    s.b0 = n0.z;
    s.b1 = n2.z;
    s.k = 2 * kPi<double> - g2 - g3;
    s.solidAngle = g0 + g1 - s.k;
    if (!std::isfinite(s.solidAngle)) s.solidAngle = 0;
    return s;
}

}  // namespace lamina::render
