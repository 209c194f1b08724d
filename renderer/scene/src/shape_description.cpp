#include "lamina/scene/shape_description.h"

#include <limits>

#include "lamina/core/overloaded.h"

namespace lamina::render {

double QuadricDesc::area() const {
    if (kind == Quadric::Disk)
        return 0.5 * phiMax * (radius - innerRadius) * (radius + innerRadius);
    return phiMax * radius * (zMax - zMin);
}

void QuadricDesc::bounds(Vec3d& lo, Vec3d& hi) const {
    // The frame's box (the disk's is flat), its corners carried to the shape's space.
    const double z0 = kind == Quadric::Disk ? 0.0 : zMin, z1 = kind == Quadric::Disk ? 0.0 : zMax;
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p =
            toShapeSpace(Vec3d((corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius,
                               (corner & 4) ? z1 : z0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

void shapeBounds(const ShapeDesc& shape, Vec3d& lo, Vec3d& hi) {
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = -lo;
    std::visit(Overloaded{[&](const MeshDesc& m) {
                              for (const Vec3<float>& p : m.positions) {
                                  lo = glm::min(lo, Vec3d(p));
                                  hi = glm::max(hi, Vec3d(p));
                              }
                          },
                          [&](const SphereDesc& s) {
                              lo = s.center - s.radius;
                              hi = s.center + s.radius;
                          },
                          [&](const DiskDesc& d) {
                              lo = d.center - d.radius;
                              hi = d.center + d.radius;
                          },
                          [&](const QuadricDesc& q) { q.bounds(lo, hi); },
                          [&](const CurvesDesc& c) {
                              // A Bezier segment lies in its control points' hull.
                              for (std::size_t i = 0; i < c.points.size(); ++i) {
                                  const double r = c.radii[i];
                                  lo = glm::min(lo, Vec3d(c.points[i]) - r);
                                  hi = glm::max(hi, Vec3d(c.points[i]) + r);
                              }
                          }},
               shape);
}

void boundingBox(const std::vector<ShapeDesc>& shapes, Vec3d& lo, Vec3d& hi) {
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (const ShapeDesc& shape : shapes) {
        Vec3d slo, shi;
        shapeBounds(shape, slo, shi);
        lo = glm::min(lo, slo);
        hi = glm::max(hi, shi);
    }
}

}  // namespace lamina::render
