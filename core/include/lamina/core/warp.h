// Warps from the unit square to common domains, each with the density of what it returns.
// Every function takes a point u in [0,1)^2; directions are in the local frame (z up).
#pragma once

#include <type_traits>

#include "lamina/core/frame.h"

namespace lamina {

/// Concentric map of the square to the unit disk: Shirley and Chiu 1997, "A Low Distortion
/// Map Between Disk and Square" (JGT 2(3)). Area-preserving up to the constant pi/4.
template <typename T>
Vec2<T> squareToUniformDiskConcentric(const Vec2<T>& u) {
    const T x = T(2) * u.x - T(1), y = T(2) * u.y - T(1);
    if (x == T(0) && y == T(0)) return Vec2<T>(T(0));
    if constexpr (std::is_same_v<T, float>) {
        // The angle is (pi/4) t in the first case, pi/2 - (pi/4) t in the second, |t| <= 1:
        // the sine and cosine of (pi/4) t, swapped in the second case (cos(pi/2 - a) is
        // sin(a)), by the polynomial for |a| <= pi/4.
        const bool xMajor = std::abs(x) > std::abs(y);
        const float r = xMajor ? x : y;
        const SinCos sc = sinCosWithinQuarterPi((kPi<float> / 4.0f) * (xMajor ? y / x : x / y));
        return xMajor ? Vec2<T>(r * sc.cos, r * sc.sin) : Vec2<T>(r * sc.sin, r * sc.cos);
    }
    T r, phi;
    if (std::abs(x) > std::abs(y)) {
        r = x;
        phi = (kPi<T> / T(4)) * (y / x);
    } else {
        r = y;
        phi = (kPi<T> / T(2)) - (kPi<T> / T(4)) * (x / y);
    }
    return Vec2<T>(r * std::cos(phi), r * std::sin(phi));
}

template <typename T>
T uniformDiskPdf(const Vec2<T>& p) {
    return p.x * p.x + p.y * p.y <= T(1) ? kInvPi<T> : T(0);
}

/// Uniform on the unit sphere; density 1 / (4 pi) per steradian.
template <typename T>
Vec3<T> squareToUniformSphere(const Vec2<T>& u) {
    const T z = T(1) - T(2) * u.x;
    const T r = safeSqrt(T(1) - z * z);
    const T phi = T(2) * kPi<T> * u.y;
    return Vec3<T>(r * std::cos(phi), r * std::sin(phi), z);
}

template <typename T>
T uniformSpherePdf() {
    return kInv4Pi<T>;
}

/// Uniform on the upper hemisphere (z >= 0); density 1 / (2 pi).
template <typename T>
Vec3<T> squareToUniformHemisphere(const Vec2<T>& u) {
    const T z = u.x;
    const T r = safeSqrt(T(1) - z * z);
    const T phi = T(2) * kPi<T> * u.y;
    return Vec3<T>(r * std::cos(phi), r * std::sin(phi), z);
}

template <typename T>
T uniformHemispherePdf(const Vec3<T>& w) {
    return w.z >= T(0) ? kInv2Pi<T> : T(0);
}

/// Cosine-weighted upper hemisphere by projecting the concentric disk up (Malley's method);
/// density cos(theta) / pi.
template <typename T>
Vec3<T> squareToCosineHemisphere(const Vec2<T>& u) {
    const Vec2<T> d = squareToUniformDiskConcentric(u);
    const T z = safeSqrt(T(1) - d.x * d.x - d.y * d.y);
    return Vec3<T>(d.x, d.y, z);
}

template <typename T>
T cosineHemispherePdf(const Vec3<T>& w) {
    return w.z > T(0) ? w.z * kInvPi<T> : T(0);
}

/// Uniform over the cone of directions around +z with cos(theta) >= cosThetaMax; density
/// 1 / (2 pi (1 - cosThetaMax)).
template <typename T>
Vec3<T> squareToUniformCone(const Vec2<T>& u, T cosThetaMax) {
    const T cosTheta = (T(1) - u.x) + u.x * cosThetaMax;
    const T sinTheta = safeSqrt(T(1) - cosTheta * cosTheta);
    const T phi = T(2) * kPi<T> * u.y;
    return Vec3<T>(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

template <typename T>
T uniformConePdf(const Vec3<T>& w, T cosThetaMax) {
    return w.z >= cosThetaMax ? T(1) / (T(2) * kPi<T> * (T(1) - cosThetaMax)) : T(0);
}

/// Uniform barycentric coordinates (b0, b1) over a triangle, b2 = 1 - b0 - b1, by the
/// square-root parameterisation (Turk 1990). In the (b0, b1) plane the density is 2; on a
/// triangle of area A it is 1 / A.
template <typename T>
Vec2<T> squareToUniformTriangle(const Vec2<T>& u) {
    const T su = std::sqrt(u.x);
    return Vec2<T>(T(1) - su, u.y * su);
}

template <typename T>
T uniformTrianglePdf(const Vec2<T>& b) {
    return (b.x >= T(0) && b.y >= T(0) && b.x + b.y <= T(1)) ? T(2) : T(0);
}

}  // namespace lamina
