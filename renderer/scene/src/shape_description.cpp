#include "lamina/scene/shape_description.h"

#include <limits>

#include "lamina/core/overloaded.h"

namespace lamina::render {

void boundingBox(const std::vector<ShapeDesc>& shapes, Vec3d& lo, Vec3d& hi) {
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (const ShapeDesc& shape : shapes)
        std::visit(Overloaded{[&](const MeshDesc& m) {
                                  for (const Vec3<float>& p : m.positions) {
                                      lo = glm::min(lo, Vec3d(p));
                                      hi = glm::max(hi, Vec3d(p));
                                  }
                              },
                              [&](const SphereDesc& s) {
                                  lo = glm::min(lo, s.center - s.radius);
                                  hi = glm::max(hi, s.center + s.radius);
                              },
                              [&](const DiskDesc& d) {
                                  lo = glm::min(lo, d.center - d.radius);
                                  hi = glm::max(hi, d.center + d.radius);
                              }},
                   shape);
}

}  // namespace lamina::render
