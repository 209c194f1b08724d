// Robust scalar helpers shared by every library. Each guards the edge case that turns a
// rounding error into a NaN (sqrt of -1e-9, acos of 1 + 1e-7, ...).
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <numbers>

namespace lamina {

template <std::floating_point T>
inline constexpr T kPi = std::numbers::pi_v<T>;
template <std::floating_point T>
inline constexpr T kInvPi = std::numbers::inv_pi_v<T>;
template <std::floating_point T>
inline constexpr T kInv2Pi = T(0.5) * std::numbers::inv_pi_v<T>;
template <std::floating_point T>
inline constexpr T kInv4Pi = T(0.25) * std::numbers::inv_pi_v<T>;

template <typename T>
constexpr T sqr(T x) {
    return x * x;
}

template <std::floating_point T>
constexpr T clamp(T x, T lo, T hi) {
    // std::clamp would pass a NaN through; a NaN becomes `lo` here.
    return x > lo ? (x < hi ? x : hi) : lo;
}

template <std::floating_point T>
constexpr T saturate(T x) {
    return clamp(x, T(0), T(1));
}

template <std::floating_point T>
inline T safeSqrt(T x) {
    return std::sqrt(std::max(x, T(0)));
}

template <std::floating_point T>
inline T safeAcos(T x) {
    return std::acos(clamp(x, T(-1), T(1)));
}

template <std::floating_point T>
inline T safeAsin(T x) {
    return std::asin(clamp(x, T(-1), T(1)));
}

/// a / b, or `fallback` when the quotient is not finite (b == 0, overflow, NaN input).
template <std::floating_point T>
inline T safeDiv(T a, T b, T fallback = T(0)) {
    const T q = a / b;
    return std::isfinite(q) ? q : fallback;
}

template <std::floating_point T>
constexpr T lerp(T t, T a, T b) {
    return (T(1) - t) * a + t * b;
}

template <std::floating_point T>
constexpr T radians(T degrees) {
    return degrees * (kPi<T> / T(180));
}

template <std::floating_point T>
constexpr T degrees(T rad) {
    return rad * (T(180) / kPi<T>);
}

/// x^5 without pow(): the Schlick Fresnel exponent.
template <typename T>
constexpr T pow5(T x) {
    const T x2 = x * x;
    return x2 * x2 * x;
}

/// 1 - (1 - c)^5 for c in [0, 1] without the cancellation of the direct form at small c
/// (where it is ~5c): -expm1(5 log1p(-c)).
template <typename T>
T oneMinusPow5OfComplement(T c) {
    if (c >= T(1)) return T(1);
    return -std::expm1(T(5) * std::log1p(-c));
}

/// Evaluates the polynomial c[0] + c[1] x + c[2] x^2 + ... by Horner's rule.
template <std::floating_point T, std::size_t N>
constexpr T evalPolynomial(T x, const T (&c)[N]) {
    T result = c[N - 1];
    for (std::size_t i = N - 1; i-- > 0;)
        result = result * x + c[i];
    return result;
}

/// The smallest T strictly below 1: what a uniform random number in [0, 1) may reach.
template <std::floating_point T>
inline constexpr T kOneMinusEpsilon = T(1) - std::numeric_limits<T>::epsilon() / T(2);

}  // namespace lamina
