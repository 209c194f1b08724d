// A ray with its valid parametric interval [tMin, tMax].
#pragma once

#include <limits>

#include "lamina/core/vector.h"

namespace lamina {

struct Ray {
    Vec3f origin{0.0f};
    Vec3f direction{0.0f, 0.0f, 1.0f};
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();

    Ray() = default;
    Ray(const Vec3f& o, const Vec3f& d, float tmax = std::numeric_limits<float>::infinity())
        : origin(o), direction(d), tMax(tmax) {}

    Vec3f operator()(float t) const { return origin + t * direction; }
};

}  // namespace lamina
