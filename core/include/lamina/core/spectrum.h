// The two spectrum representations of the dual-mode design (docs/spectral.md):
//   Rgb<T>                  three linear Rec.709 coefficients,
//   SampledSpectrum<T, N>   values at the N wavelengths a path carries.
// Both share one implementation (a fixed-size coefficient array with component-wise
// arithmetic) but are distinct types, so an RGB value can never be mixed with samples at
// wavelengths by accident. Templated on T so BSDF code compiles in float and double.
#pragma once

#include <array>
#include <cmath>
#include <concepts>

#include "lamina/core/math.h"

namespace lamina {

struct RgbTag {};
struct SampledTag {};

template <std::floating_point T, int N, typename Tag>
class CoefficientSpectrum {
  public:
    using Float = T;
    static constexpr int kSize = N;

    constexpr CoefficientSpectrum() : c_{} {}
    constexpr explicit CoefficientSpectrum(T v) { c_.fill(v); }
    template <typename... A>
    requires(sizeof...(A) == N && N > 1 &&
             (std::convertible_to<A, T> && ...)) constexpr CoefficientSpectrum(A... v)
        : c_{static_cast<T>(v)...} {}
    /// Precision conversion (float <-> double) of the same representation.
    template <std::floating_point U>
    requires(!std::same_as<U, T>) constexpr explicit CoefficientSpectrum(
        const CoefficientSpectrum<U, N, Tag>& o) {
        for (int i = 0; i < N; ++i)
            c_[i] = static_cast<T>(o[i]);
    }

    constexpr T& operator[](int i) { return c_[i]; }
    constexpr const T& operator[](int i) const { return c_[i]; }

#define LAMINA_SPECTRUM_OP(op)                                                       \
    constexpr CoefficientSpectrum& operator op##=(const CoefficientSpectrum& o) {    \
        for (int i = 0; i < N; ++i)                                                  \
            c_[i] op## = o.c_[i];                                                    \
        return *this;                                                                \
    }                                                                                \
    constexpr CoefficientSpectrum& operator op##=(T s) {                             \
        for (int i = 0; i < N; ++i)                                                  \
            c_[i] op## = s;                                                          \
        return *this;                                                                \
    }                                                                                \
    friend constexpr CoefficientSpectrum operator op(CoefficientSpectrum a,          \
                                                     const CoefficientSpectrum& b) { \
        return a op## = b;                                                           \
    }                                                                                \
    friend constexpr CoefficientSpectrum operator op(CoefficientSpectrum a, T s) {   \
        return a op## = s;                                                           \
    }
    LAMINA_SPECTRUM_OP(+)
    LAMINA_SPECTRUM_OP(-)
    LAMINA_SPECTRUM_OP(*)
    LAMINA_SPECTRUM_OP(/)
#undef LAMINA_SPECTRUM_OP

    friend constexpr CoefficientSpectrum operator*(T s, CoefficientSpectrum a) {
        return a *= s;
    }
    friend constexpr CoefficientSpectrum operator+(T s, CoefficientSpectrum a) {
        return a += s;
    }
    friend constexpr CoefficientSpectrum operator-(T s, const CoefficientSpectrum& a) {
        return CoefficientSpectrum(s) - a;
    }
    friend constexpr CoefficientSpectrum operator/(T s, const CoefficientSpectrum& a) {
        return CoefficientSpectrum(s) / a;
    }
    constexpr CoefficientSpectrum operator-() const {
        return CoefficientSpectrum(T(0)) - *this;
    }
    constexpr bool operator==(const CoefficientSpectrum&) const = default;

    constexpr bool isZero() const {
        for (T v : c_)
            if (v != T(0)) return false;
        return true;
    }
    constexpr T maxValue() const {
        T m = c_[0];
        for (T v : c_)
            m = v > m ? v : m;
        return m;
    }
    constexpr T minValue() const {
        T m = c_[0];
        for (T v : c_)
            m = v < m ? v : m;
        return m;
    }
    constexpr T average() const {
        T s = 0;
        for (T v : c_)
            s += v;
        return s / T(N);
    }
    bool isFinite() const {
        for (T v : c_)
            if (!std::isfinite(v)) return false;
        return true;
    }
    bool hasNegative() const {
        for (T v : c_)
            if (v < T(0)) return true;
        return false;
    }

    /// Applies a scalar function to every coefficient.
    template <typename F>
    friend CoefficientSpectrum map(const CoefficientSpectrum& s, F&& f) {
        CoefficientSpectrum r;
        for (int i = 0; i < N; ++i)
            r[i] = f(s[i]);
        return r;
    }
    /// Component-wise combination of two spectra.
    template <typename F>
    friend CoefficientSpectrum zipWith(const CoefficientSpectrum& a, const CoefficientSpectrum& b,
                                       F&& f) {
        CoefficientSpectrum r;
        for (int i = 0; i < N; ++i)
            r[i] = f(a[i], b[i]);
        return r;
    }
    friend CoefficientSpectrum sqrt(const CoefficientSpectrum& s) {
        return map(s, [](T v) { return safeSqrt(v); });
    }
    friend CoefficientSpectrum exp(const CoefficientSpectrum& s) {
        return map(s, [](T v) { return std::exp(v); });
    }
    friend CoefficientSpectrum clampZero(const CoefficientSpectrum& s) {
        return map(s, [](T v) { return v > T(0) ? v : T(0); });
    }
    friend CoefficientSpectrum saturate(const CoefficientSpectrum& s) {
        return map(s, [](T v) { return lamina::saturate(v); });
    }
    friend CoefficientSpectrum min(const CoefficientSpectrum& a, const CoefficientSpectrum& b) {
        return zipWith(a, b, [](T x, T y) { return x < y ? x : y; });
    }
    friend CoefficientSpectrum max(const CoefficientSpectrum& a, const CoefficientSpectrum& b) {
        return zipWith(a, b, [](T x, T y) { return x > y ? x : y; });
    }
    friend CoefficientSpectrum lerp(T t, const CoefficientSpectrum& a,
                                    const CoefficientSpectrum& b) {
        return (T(1) - t) * a + t * b;
    }
    /// a / b, 0 where b is 0 (used where a zero denominator means "no contribution").
    friend CoefficientSpectrum safeDiv(const CoefficientSpectrum& a, const CoefficientSpectrum& b) {
        return zipWith(a, b, [](T x, T y) { return y != T(0) ? x / y : T(0); });
    }

  private:
    std::array<T, N> c_;
};

template <std::floating_point T>
using Rgb = CoefficientSpectrum<T, 3, RgbTag>;

/// The number of wavelengths a spectral path carries (hero wavelength + 3 rotations).
inline constexpr int kSpectrumSamples = 4;

template <std::floating_point T, int N = kSpectrumSamples>
using SampledSpectrum = CoefficientSpectrum<T, N, SampledTag>;

using Rgbf = Rgb<float>;
using Rgbd = Rgb<double>;

/// Relative luminance Y of linear Rec.709 RGB (ITU-R BT.709-6, the Y row of its RGB->XYZ
/// matrix for the D65 white).
template <std::floating_point T>
constexpr T luminance(const Rgb<T>& c) {
    return T(0.2126) * c[0] + T(0.7152) * c[1] + T(0.0722) * c[2];
}

template <typename S>
concept SpectrumType = requires(S s) {
    typename S::Float;
    { S::kSize } -> std::convertible_to<int>;
};

}  // namespace lamina
