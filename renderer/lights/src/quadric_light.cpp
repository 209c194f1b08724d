#include <algorithm>

#include "lamina/geometry/quadric.h"
#include "lamina/lights/area_lights.h"

namespace lamina::render {

QuadricLight::QuadricLight(const QuadricDesc& q) : AreaLight(*q.emission, q.area()), quadric_(q) {}

// By area as AreaLight::sample, in double precision and with the density dist^2 / (|cos| A).
std::optional<LightSample> QuadricLight::sample(const Vec3f& refF, const Vec2f& u) const {
    const Vec3d ref(refF);
    const AreaPoint a = samplePoint(u);
    return towards(ref, a.p, a.n, solidAngleDensity(ref, a));
}

std::optional<LightBounds> QuadricLight::bounds() const {
    if (!(area_ > 0)) return std::nullopt;
    Vec3d lo, hi;
    quadric_.bounds(lo, hi);
    if (quadric_.kind == Quadric::Disk)
        return flatBounds(Vec3f(lo), Vec3f(hi),
                          Vec3f(quadric_.axes[2] * (quadric_.flipNormals ? -1.0 : 1.0)));
    const double r = quadric_.radius;
    const double silhouette = quadric_.kind == Quadric::Sphere
                                  ? kPi<double> * r * r
                                  : 2 * r * (quadric_.zMax - quadric_.zMin);
    LightBounds b;
    b.lower = Vec3f(lo);
    b.upper = Vec3f(hi);
    b.cosThetaO = -1.0f;
    b.cosThetaE = 0.0f;
    b.intensity = radianceLuminance() * float(std::min(silhouette, area_));
    b.twoSided = twoSided_;
    return b;
}

AreaLight::AreaPoint QuadricLight::samplePoint(const Vec2f& u) const {
    const Vec3d local = sampleQuadric(quadric_, Vec2<double>(u));
    return {quadric_.toShapeSpace(local), quadricNormal(quadric_, local)};
}

}  // namespace lamina::render
