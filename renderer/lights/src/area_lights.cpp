#include "lamina/lights/area_lights.h"

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
