// Vector types on GLM, templated on the floating-point type so that the same code compiles in
// float (rendering) and double (the numerical-stability reference).
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>

#include "lamina/core/math.h"

namespace lamina {

template <typename T>
using Vec2 = glm::vec<2, T, glm::defaultp>;
template <typename T>
using Vec3 = glm::vec<3, T, glm::defaultp>;
template <typename T>
using Vec4 = glm::vec<4, T, glm::defaultp>;
template <typename T>
using Mat3 = glm::mat<3, 3, T, glm::defaultp>;
template <typename T>
using Mat4 = glm::mat<4, 4, T, glm::defaultp>;

using Vec2f = Vec2<float>;
using Vec3f = Vec3<float>;
using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;

template <typename T>
inline T lengthSquared(const Vec3<T>& v) {
    return glm::dot(v, v);
}

/// Normalises v; returns the zero vector for a zero-length input instead of NaNs.
template <typename T>
inline Vec3<T> safeNormalize(const Vec3<T>& v) {
    const T len2 = glm::dot(v, v);
    if (!(len2 > T(0)) || !std::isfinite(len2)) return Vec3<T>(T(0));
    return v / std::sqrt(len2);
}

/// Normalises v at any magnitude a float vector can have. The float dot product overflows for
/// |v| above about 1.8e19 (a triangle's edge cross product in a scene 1e8 times the Cornell
/// box's size) and loses its precision below about 1e-19, where safeNormalize would return
/// zero or an inaccurate vector; there the length is taken in double. Elsewhere the result is
/// safeNormalize's, bit for bit.
inline Vec3<float> normalizeAnyScale(const Vec3<float>& v) {
    const float len2 = glm::dot(v, v);
    if (std::isfinite(len2) && len2 >= std::numeric_limits<float>::min())
        return v / std::sqrt(len2);
    return Vec3<float>(safeNormalize(Vec3<double>(v)));
}

template <typename T>
inline bool isFinite(const Vec3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Mirror reflection of `w` about the normal `n` (both pointing away from the surface).
template <typename T>
inline Vec3<T> reflect(const Vec3<T>& w, const Vec3<T>& n) {
    return T(2) * glm::dot(w, n) * n - w;
}

/// Component of v in the direction of n, flipped so that it lies on the side of `ref`.
template <typename T>
inline Vec3<T> faceForward(const Vec3<T>& n, const Vec3<T>& ref) {
    return glm::dot(n, ref) < T(0) ? -n : n;
}

}  // namespace lamina
