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

/// sin(a) and cos(a) for |a| <= pi/4 in single precision, by their Taylor polynomials in
/// a^2. There the remainders are below |a|^11 / 11! (at most 1.8e-9, and relative to sin(a)
/// at most 2.5e-9) and a^12 / 12! (1.2e-10, with cos(a) >= 0.707), far under float's
/// rounding, so the error is that of the multiply-adds, a few ulps. The concentric disk map's
/// angles lie in this range, and a polynomial is ten multiply-adds where sincosf first
/// reduces its argument (it was 2% of a Cornell box render).
struct SinCos {
    float sin, cos;
};
inline SinCos sinCosWithinQuarterPi(float a) {
    const float a2 = a * a;
    // 1 / (2k + 1)! and 1 / (2k)!, alternating in sign.
    constexpr float kSin[] = {1.0f, -1.0f / 6.0f, 1.0f / 120.0f, -1.0f / 5040.0f, 1.0f / 362880.0f};
    constexpr float kCos[] = {1.0f,           -0.5f,           1.0f / 24.0f,
                              -1.0f / 720.0f, 1.0f / 40320.0f, -1.0f / 3628800.0f};
    return {a * evalPolynomial(a2, kSin), evalPolynomial(a2, kCos)};
}

/// The smallest T strictly below 1: what a uniform random number in [0, 1) may reach.
template <std::floating_point T>
inline constexpr T kOneMinusEpsilon = T(1) - std::numeric_limits<T>::epsilon() / T(2);

}  // namespace lamina
