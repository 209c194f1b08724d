// A spectrum resampled in float at every whole nanometre of the rendered range [360, 830] nm
// and interpolated linearly between the samples: what spectral mode evaluates at a path's
// four wavelengths when the spectrum itself is slow (an RGB colour upsampled as an
// illuminant is a sigmoid of a polynomial, a square root and a division in double, times a
// D65 lookup: about 15 ns per wavelength, against 2 ns for two loads and a lerp here).
//
// Accuracy: a curve that is piecewise linear on knots at whole nanometres (the CIE colour
// matching functions and illuminants, given at 5 nm from 360 nm) is reproduced to float
// rounding. A smooth curve errs by at most h^2/8 max|f''| with h = 1 nm: below 3e-4 of the
// value for saturated colours upsampled as illuminants (Jakob and Hanika 2019's sigmoids times
// D65) and for a 2700 K black body, far below any render's noise. A table whose knots fall
// between whole nanometres loses detail narrower than 1 nm.
// tests/spectral/resampled_spectrum_test.cpp bounds these.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include "lamina/core/float4.h"
#include "lamina/core/spectrum.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina {

class ResampledSpectrum {
  public:
    static constexpr int kSamples = static_cast<int>(kLambdaMax - kLambdaMin) + 1;  // 471

    /// Where a wavelength falls: between samples i and i + 1, at fraction t. Wavelengths
    /// outside the range are clamped to its ends (the renderer draws none there).
    struct Position {
        int i;
        float t;
    };
    static Position locate(float nm) {
        const float x = std::clamp(nm - float(kLambdaMin), 0.0f, float(kSamples - 1));
        const int i = std::min(static_cast<int>(x), kSamples - 2);
        return {i, x - float(i)};
    }

    /// Samples f(nm) at nm = 360, 361, ..., 830.
    template <typename F>
    explicit ResampledSpectrum(F&& f) {
        for (int i = 0; i < kSamples; ++i)
            values_[std::size_t(i)] = float(f(kLambdaMin + double(i)));
    }

    float at(const Position& p) const {
        const float a = values_[std::size_t(p.i)], b = values_[std::size_t(p.i) + 1];
        return a + p.t * (b - a);
    }
    float operator()(float nm) const { return at(locate(nm)); }

    /// Where a path's wavelengths fall (locate() of each lane): found once per path, it serves
    /// every table the path reads at them (its emitters, the film's colour matching).
    template <int N>
    struct Positions {
        std::array<std::int32_t, N> i{};
        std::array<float, N> t{};
    };
    template <int N>
    static Positions<N> locate(const SampledWavelengths<float, N>& lambda) {
        Positions<N> p;
        if constexpr (N == 4) {  // locate() in four lanes: the same operations, in one register
            using namespace simd;
            Float4 x =
                Float4{lambda[0], lambda[1], lambda[2], lambda[3]} - splat(float(kLambdaMin));
            x = select(x < splat(0.0f), splat(0.0f), x);
            x = select(splat(float(kSamples - 1)) < x, splat(float(kSamples - 1)), x);
            Int4 i = truncate(x);
            i = i > Int4{} + (kSamples - 2) ? Int4{} + (kSamples - 2) : i;
            std::memcpy(p.i.data(), &i, sizeof i);
            store(p.t.data(), x - toFloat(i));
        } else {
            for (int k = 0; k < N; ++k) {
                const Position q = locate(lambda[k]);
                p.i[std::size_t(k)] = q.i;
                p.t[std::size_t(k)] = q.t;
            }
        }
        return p;
    }

    /// The spectrum at a path's wavelengths.
    template <int N>
    SampledSpectrum<float, N> at(const Positions<N>& p) const {
        SampledSpectrum<float, N> s;
        if constexpr (N == 4) {  // at() in four lanes
            using namespace simd;
            Float4 a, b;
            for (int k = 0; k < 4; ++k) {
                a[k] = values_[std::size_t(p.i[std::size_t(k)])];
                b[k] = values_[std::size_t(p.i[std::size_t(k)]) + 1];
            }
            store(&s[0], a + load(p.t.data()) * (b - a));
        } else {
            for (int k = 0; k < N; ++k)
                s[k] = at(Position{p.i[std::size_t(k)], p.t[std::size_t(k)]});
        }
        return s;
    }
    template <int N>
    SampledSpectrum<float, N> at(const SampledWavelengths<float, N>& lambda) const {
        return at(locate(lambda));
    }

    /// The sample at nm = 360 + i.
    float value(int i) const { return values_[std::size_t(i)]; }

  private:
    std::array<float, kSamples> values_{};
};

}  // namespace lamina
