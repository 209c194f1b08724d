#include "lamina/render/area_lights.h"

#include <algorithm>

#include "lamina/core/warp.h"

namespace lamina::render {

namespace {

// Converts an area density at a light point to solid angle at `ref`.
float areaToSolidAngle(float pdfArea, const Vec3f& ref, const Vec3f& p, const Vec3f& n) {
    const Vec3f d = p - ref;
    const float dist2 = glm::dot(d, d);
    const float cosLight = std::abs(glm::dot(n, d)) / std::sqrt(dist2);
    if (!(cosLight > 0.0f)) return 0.0f;
    return pdfArea * dist2 / cosLight;
}

}  // namespace

AreaLight::AreaLight(const EmissionDesc& e, double area)
    : twoSided_(e.twoSided), color_(e.radiance, e.spectrum), area_(area) {}

std::optional<LightSample> AreaLight::sample(const Vec3f& ref, const Vec2f& u) const {
    if (!(area_ > 0)) return std::nullopt;
    const AreaPoint a = samplePoint(u);
    const Vec3f p(a.p), n(a.n);
    const Vec3f d = p - ref;
    const float dist = glm::length(d);
    if (!(dist > 0.0f)) return std::nullopt;
    const Vec3f wi = d / dist;
    const float cosLight = glm::dot(n, -wi);
    if (!twoSided_ && !(cosLight > 0.0f)) return std::nullopt;
    const float pdf = areaToSolidAngle(float(1.0 / area_), ref, p, n);
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
    return LightSample{wi, dist, {&color_, 1.0f}, pdf, false, p, cosLight > 0 ? n : -n};
}

float AreaLight::pdf(const Vec3f& ref, const SurfaceHit& hit) const {
    return areaToSolidAngle(float(1.0 / area_), ref, hit.p, hit.ng);
}

Emission AreaLight::radiance(const SurfaceHit& hit, const Vec3f& w) const {
    if (twoSided_ || glm::dot(hit.ng, w) > 0.0f) return {&color_, 1.0f};
    return {};
}

double AreaLight::power() const {
    return (twoSided_ ? 2.0 : 1.0) * kPi<double> * area_ * luminance(color_.rgbDouble());
}

float AreaLight::radianceLuminance() const {
    return float(luminance(color_.rgbDouble()));
}

LightBounds AreaLight::flatBounds(const Vec3f& lower, const Vec3f& upper, const Vec3f& n) const {
    LightBounds b;
    b.lower = lower;
    b.upper = upper;
    b.axis = n;
    b.cosThetaO = 1.0f;
    b.cosThetaE = 0.0f;
    b.intensity = radianceLuminance() * float(area_);
    b.twoSided = twoSided_;
    return b;
}

std::optional<EmissionSample> AreaLight::sampleEmission(const Vec2f& uPosition,
                                                        const Vec2f& uDirection) const {
    if (!(area_ > 0)) return std::nullopt;
    const AreaPoint a = samplePoint(uPosition);
    const Vec3f p(a.p), n(a.n);
    Vec2f u = uDirection;
    Vec3f normal = n;
    if (twoSided_) {
        const bool back = u.x >= 0.5f;
        u.x = std::min(2.0f * (back ? u.x - 0.5f : u.x), kOneMinusEpsilon<float>);
        if (back) normal = -n;
    }
    const Vec3f local = squareToCosineHemisphere(u);
    if (!(local.z > 0.0f)) return std::nullopt;
    EmissionSample e;
    e.point = p;
    e.normal = normal;
    e.direction = Frame<float>::fromNormal(normal).toWorld(local);
    e.radiance = {&color_, 1.0f};
    e.pdfPosition = float(1.0 / area_);
    e.pdfDirection = local.z * kInvPi<float> * (twoSided_ ? 0.5f : 1.0f);
    return e;
}

EmissionPdf AreaLight::emissionPdf(const Vec3f&, const Vec3f& normal,
                                   const Vec3f& direction) const {
    const float c = glm::dot(normal, direction);
    if (!twoSided_ && !(c > 0.0f)) return {float(1.0 / area_), 0.0f};
    return {float(1.0 / area_), std::abs(c) * kInvPi<float> * (twoSided_ ? 0.5f : 1.0f)};
}

double AreaLight::solidAngleDensity(const Vec3d& ref, const AreaPoint& a) const {
    const Vec3d d = a.p - ref;
    const double dist2 = glm::dot(d, d);
    const double cosL = std::abs(glm::dot(a.n, d)) / std::sqrt(dist2);
    if (!(cosL > 0)) return 0;
    return dist2 / (cosL * area_);
}

std::optional<LightSample> AreaLight::towards(const Vec3d& ref, const Vec3d& p, const Vec3d& n,
                                              double pdf) const {
    const Vec3d d = p - ref;
    const double dist = glm::length(d);
    if (!(dist > 0) || !(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
    const Vec3f wi = Vec3f(d / dist);
    const bool front = glm::dot(n, -d) > 0;
    if (!front && !twoSided_) return std::nullopt;
    return LightSample{wi,    float(dist), {&color_, 1.0f},      float(pdf),
                       false, Vec3f(p),    Vec3f(front ? n : -n)};
}

TriangleLight::TriangleLight(const MeshDesc& mesh, std::size_t triangle)
    : AreaLight(*mesh.emission, 0.0) {
    const auto& t = mesh.triangles[triangle];
    p0_ = mesh.positions[t[0]];
    p1_ = mesh.positions[t[1]];
    p2_ = mesh.positions[t[2]];
    const Vec3d c = glm::cross(Vec3d(p1_ - p0_), Vec3d(p2_ - p0_));
    area_ = 0.5 * glm::length(c);
    n_ = Vec3f(glm::normalize(c));
}

std::optional<LightBounds> TriangleLight::bounds() const {
    if (!(area_ > 0)) return std::nullopt;
    return flatBounds(glm::min(p0_, glm::min(p1_, p2_)), glm::max(p0_, glm::max(p1_, p2_)), n_);
}

AreaLight::AreaPoint TriangleLight::samplePoint(const Vec2f& u) const {
    const Vec2f b = squareToUniformTriangle(u);
    return {Vec3d(b.x * p0_ + b.y * p1_ + (1.0f - b.x - b.y) * p2_), Vec3d(n_)};
}

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
    if (bySolidAngle(height(Vec3d(refF))))
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

DiskLight::DiskLight(const DiskDesc& d)
    : AreaLight(*d.emission, kPi<double> * d.radius * d.radius),
      disk_(d),
      frame_(Frame<double>::fromNormal(d.normal)) {}

// By area as AreaLight::sample, in double precision and with the density dist * dist /
// (|cos| A).
std::optional<LightSample> DiskLight::sample(const Vec3f& refF, const Vec2f& u) const {
    const Vec3d ref(refF);
    const Vec3d p = samplePoint(u).p;
    const Vec3d d = p - ref;
    const double dist = glm::length(d);
    const double cosL = glm::dot(disk_.normal, -d) / dist;
    return towards(ref, p, disk_.normal, dist * dist / (std::abs(cosL) * area_));
}

std::optional<LightBounds> DiskLight::bounds() const {
    if (!(area_ > 0)) return std::nullopt;
    // Along each axis the disk reaches r sqrt(1 - n_k^2) from its centre.
    const Vec3d n = disk_.normal;
    const Vec3d reach = disk_.radius * Vec3d(std::sqrt(std::max(0.0, 1.0 - n.x * n.x)),
                                             std::sqrt(std::max(0.0, 1.0 - n.y * n.y)),
                                             std::sqrt(std::max(0.0, 1.0 - n.z * n.z)));
    return flatBounds(Vec3f(disk_.center - reach), Vec3f(disk_.center + reach), Vec3f(n));
}

AreaLight::AreaPoint DiskLight::samplePoint(const Vec2f& u) const {
    const Vec2<double> q = squareToUniformDiskConcentric(Vec2<double>(u)) * disk_.radius;
    return {disk_.center + frame_.toWorld(Vec3<double>(q.x, q.y, 0.0)), disk_.normal};
}

SphereLight::SphereLight(const SphereDesc& s)
    : AreaLight(*s.emission, 4.0 * kPi<double> * s.radius * s.radius), sphere_(s) {}

std::optional<LightSample> SphereLight::sample(const Vec3f& refF, const Vec2f& u) const {
    const Vec3d ref(refF), c = sphere_.center;
    const double r = sphere_.radius;
    const double dc2 = glm::dot(ref - c, ref - c);
    Vec3d p;
    double pdf;
    if (useCone(dc2)) {
        const double dc = std::sqrt(dc2);
        const double sin2Max = r * r / dc2;
        const double cosMax = std::sqrt(std::max(0.0, 1.0 - sin2Max));
        const double oneMinusCos = sin2Max / (1.0 + cosMax);  // stable for small cones
        // Uniform in the cone: 1 - cos(theta) uniform in [0, 1 - cos(theta_max)].
        const double omc = double(u.x) * oneMinusCos;
        const double cosT = 1.0 - omc;
        const double sinT = std::sqrt(std::max(0.0, omc * (2.0 - omc)));
        const double phi = 2.0 * kPi<double> * double(u.y);
        const Frame<double> frame = Frame<double>::fromNormal((c - ref) / dc);
        const Vec3d dir = frame.toWorld(Vec3d(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
        // The nearer intersection of the ray with the sphere (tangent: the closest point).
        const double b = glm::dot(dir, c - ref);
        const double disc = std::max(0.0, r * r - (dc2 - b * b));
        const double t = b - std::sqrt(disc);
        p = ref + t * dir;
        pdf = 1.0 / (2.0 * kPi<double> * oneMinusCos);
    } else {
        const AreaPoint a = samplePoint(u);
        p = a.p;
        pdf = solidAngleDensity(ref, a);
    }
    Vec3d n = glm::normalize(p - c);
    if (sphere_.flipNormals) n = -n;
    // As towards(), but the side is decided in single precision, on wi: the two tests can
    // disagree at grazing angles, and the sphere has always used this one.
    const Vec3d d = p - ref;
    const double dist = glm::length(d);
    if (!(dist > 0.0) || !(pdf > 0.0) || !std::isfinite(pdf)) return std::nullopt;
    const Vec3f wi = Vec3f(d / dist);
    const bool front = glm::dot(Vec3f(n), -wi) > 0.0f;
    if (!front && !twoSided_) return std::nullopt;
    return LightSample{wi,
                       float(dist),
                       {&color_, 1.0f},
                       float(pdf),
                       false,
                       Vec3f(p),
                       front ? Vec3f(n) : -Vec3f(n)};
}

float SphereLight::pdf(const Vec3f& refF, const SurfaceHit& hit) const {
    const Vec3d ref(refF), c = sphere_.center;
    const double r = sphere_.radius;
    const double dc2 = glm::dot(ref - c, ref - c);
    if (useCone(dc2)) {
        const double sin2Max = r * r / dc2;
        const double cosMax = std::sqrt(std::max(0.0, 1.0 - sin2Max));
        return float(1.0 / (2.0 * kPi<double> * sin2Max / (1.0 + cosMax)));
    }
    return AreaLight::pdf(refF, hit);
}

std::optional<LightBounds> SphereLight::bounds() const {
    if (!(sphere_.radius > 0)) return std::nullopt;
    const Vec3d c = sphere_.center, r(sphere_.radius);
    LightBounds b;
    b.lower = Vec3f(c - r);
    b.upper = Vec3f(c + r);
    b.cosThetaO = -1.0f;
    b.cosThetaE = 0.0f;
    b.intensity = radianceLuminance() * float(kPi<double> * sqr(sphere_.radius));
    return b;
}

AreaLight::AreaPoint SphereLight::samplePoint(const Vec2f& u) const {
    const Vec3d n = Vec3d(squareToUniformSphere(Vec2<double>(u)));
    return {sphere_.center + sphere_.radius * n, sphere_.flipNormals ? -n : n};
}

bool SphereLight::useCone(double dc2) const {
    return !sphere_.flipNormals && dc2 > sqr(sphere_.radius) * (1.0 + 1e-6);
}

}  // namespace lamina::render
