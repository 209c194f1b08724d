// An orthonormal basis around a normal: the local shading frame in which every BSDF works
// (z = normal). Built with the branchless construction of Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited" (JCGT 6(1)), Listing 3, which is continuous except at
// n.z = -0 and stays orthonormal to rounding error for all unit n.
#pragma once

#include "lamina/core/vector.h"

namespace lamina {

template <typename T>
struct Frame {
    Vec3<T> s{1, 0, 0};  ///< tangent
    Vec3<T> t{0, 1, 0};  ///< bitangent
    Vec3<T> n{0, 0, 1};  ///< normal

    Frame() = default;
    Frame(const Vec3<T>& s_, const Vec3<T>& t_, const Vec3<T>& n_) : s(s_), t(t_), n(n_) {}

    /// The frame around a unit normal (Duff et al. 2017).
    static Frame fromNormal(const Vec3<T>& n) {
        const T sign = std::copysign(T(1), n.z);
        const T a = T(-1) / (sign + n.z);
        const T b = n.x * n.y * a;
        return Frame(Vec3<T>(T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x),
                     Vec3<T>(b, sign + n.y * n.y * a, -n.y), n);
    }

    /// The frame around a unit normal whose tangent follows `tangent` (Gram-Schmidt); used for
    /// anisotropic materials. Falls back to fromNormal when the tangent is parallel to n.
    static Frame fromNormalTangent(const Vec3<T>& n, const Vec3<T>& tangent) {
        const Vec3<T> s = safeNormalize(tangent - n * glm::dot(n, tangent));
        if (s == Vec3<T>(T(0))) return fromNormal(n);
        return Frame(s, glm::cross(n, s), n);
    }

    Vec3<T> toLocal(const Vec3<T>& v) const {
        return Vec3<T>(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n));
    }
    Vec3<T> toWorld(const Vec3<T>& v) const { return s * v.x + t * v.y + n * v.z; }
};

using Framef = Frame<float>;

// Spherical helpers in the local frame (z up). Clamped so a unit vector whose z is
// 1 + 1e-7 after rounding still gives finite, consistent values.
template <typename T>
inline T cosTheta(const Vec3<T>& w) {
    return w.z;
}
template <typename T>
inline T absCosTheta(const Vec3<T>& w) {
    return std::abs(w.z);
}
template <typename T>
inline T cos2Theta(const Vec3<T>& w) {
    return w.z * w.z;
}
template <typename T>
inline T sin2Theta(const Vec3<T>& w) {
    return std::max(T(0), T(1) - cos2Theta(w));
}
template <typename T>
inline T sinTheta(const Vec3<T>& w) {
    return std::sqrt(sin2Theta(w));
}
template <typename T>
inline T tan2Theta(const Vec3<T>& w) {
    return sin2Theta(w) / cos2Theta(w);
}
template <typename T>
inline T cosPhi(const Vec3<T>& w) {
    const T st = sinTheta(w);
    return st == T(0) ? T(1) : clamp(w.x / st, T(-1), T(1));
}
template <typename T>
inline T sinPhi(const Vec3<T>& w) {
    const T st = sinTheta(w);
    return st == T(0) ? T(0) : clamp(w.y / st, T(-1), T(1));
}
template <typename T>
inline bool sameHemisphere(const Vec3<T>& a, const Vec3<T>& b) {
    return a.z * b.z > T(0);
}

/// Unit vector from spherical coordinates (theta from +z, phi from +x).
template <typename T>
inline Vec3<T> sphericalDirection(T sinTheta, T cosTheta, T phi) {
    return Vec3<T>(clamp(sinTheta, T(-1), T(1)) * std::cos(phi),
                   clamp(sinTheta, T(-1), T(1)) * std::sin(phi), clamp(cosTheta, T(-1), T(1)));
}

}  // namespace lamina
