// The wavelengths a spectral path carries: hero-wavelength sampling (Wilkie et al. 2014,
// "Hero Wavelength Spectral Sampling", EGSR). One hero wavelength is drawn at random; the
// other N-1 are its rotations by k/N of the range. With importance sampling the rotation is
// done in primary-sample space (u_k = frac(u + k/N), lambda_k = F^-1(u_k)), so every
// lambda_k has the same marginal density p(lambda) and the N estimates f(lambda_k)/p(lambda_k)
// are stratified over the range.
//
// The importance density follows the shape pbrt-v4 uses for visible wavelengths (Pharr,
// Jakob and Humphreys 2023, "Physically Based Rendering", 4th ed., section 4.6.4),
// sech^2(a (lambda - mu)) with a = 0.0072 / nm and mu = 538 nm, normalised over lamina's
// range [360, 830] nm, whose cdf inverts in closed form:
//   F(lambda) = (tanh(a (lambda - mu)) - t0) / (t1 - t0),  t0,1 = tanh(a (360|830 - mu)).
// The renderer draws from a piecewise-constant version of it: the range cut at the
// wavelengths F^-1(j / 256), j = 0..256, into 256 intervals of probability 1/256 each, with a
// constant density in each (1/256 over the interval's width: 1 nm near 538 nm, 15 nm at
// 830 nm where the density is lowest). That density is within 2% of sech^2 over 400-700 nm
// and 12% at the ends of the range, where the colour matching functions are nearly 0; it is
// exactly the density the samples have, so estimates stay unbiased, and drawing from it costs
// a multiply and a lerp where the closed form costs a division and a logarithm per wavelength
// (with four wavelengths per path, 10% of a spectral render of scenes/white-furnace.json).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "lamina/core/float4.h"
#include "lamina/core/spectrum.h"
#include "lamina/spectral/cie.h"

namespace lamina {

enum class WavelengthSampling { Visible, Uniform };

namespace visible_wavelengths {
inline constexpr double kA = 0.0072;
inline constexpr double kMu = 538.0;
inline constexpr int kIntervals = 256;

/// The closed-form inverse cdf of the sech^2 density (where the intervals are cut).
inline double sech2InverseCdf(double u) {
    const double t0 = std::tanh(kA * (kLambdaMin - kMu)), t1 = std::tanh(kA * (kLambdaMax - kMu));
    return std::clamp(kMu + std::atanh(t0 + u * (t1 - t0)) / kA, kLambdaMin, kLambdaMax);
}

/// The interval ends (F^-1(j / 256)) and each interval's density, in double and in float.
struct Intervals {
    std::array<double, kIntervals + 1> nm{};
    std::array<double, kIntervals> density{};
    std::array<float, kIntervals + 1> nmFloat{};
    std::array<float, kIntervals> densityFloat{};
};
inline const Intervals& intervals() {
    static const Intervals table = [] {
        Intervals t;
        for (int j = 0; j <= kIntervals; ++j)
            t.nm[j] =
                j == 0 ? kLambdaMin
                       : (j == kIntervals ? kLambdaMax : sech2InverseCdf(double(j) / kIntervals));
        for (int j = 0; j < kIntervals; ++j)
            t.density[j] = 1.0 / (kIntervals * (t.nm[j + 1] - t.nm[j]));
        for (int j = 0; j <= kIntervals; ++j)
            t.nmFloat[j] = float(t.nm[j]);
        for (int j = 0; j < kIntervals; ++j)
            t.densityFloat[j] = float(t.density[j]);
        return t;
    }();
    return table;
}

/// The density at `nm` (the interval's; 0 outside the range).
inline double pdf(double nm) {
    if (nm < kLambdaMin || nm > kLambdaMax) return 0.0;
    const Intervals& t = intervals();
    const auto upper = std::upper_bound(t.nm.begin() + 1, t.nm.end() - 1, nm);
    return t.density[std::size_t(upper - t.nm.begin() - 1)];
}

/// Where u in [0, 1) falls: interval floor(256 u) and the fraction within it. In double, where
/// it is exact for a float u (256 u only moves the exponent).
struct Position {
    int interval;
    double fraction;
};
inline Position locate(double u) {
    const double x = std::clamp(u, 0.0, 1.0) * kIntervals;
    const int j = std::min(static_cast<int>(x), kIntervals - 1);
    return {j, x - double(j)};
}

/// The wavelength at fraction f of interval j, linearly within it, and its density.
template <std::floating_point T>
T atInterval(int j, T f, T& pdfOut) {
    const Intervals& t = intervals();
    if constexpr (std::same_as<T, float>) {
        const float a = t.nmFloat[j], b = t.nmFloat[j + 1];
        pdfOut = t.densityFloat[j];
        return a + f * (b - a);
    } else {
        const T a = T(t.nm[j]), b = T(t.nm[j + 1]);
        pdfOut = T(t.density[j]);
        return a + f * (b - a);
    }
}

/// The wavelength at u in [0, 1) and its density: interval floor(256 u), linearly within it.
template <std::floating_point T>
T sample(double u, T& pdfOut) {
    const Position p = locate(u);
    return atInterval(p.interval, T(p.fraction), pdfOut);
}
inline double sample(double u) {
    double p;
    return sample(u, p);
}

/// The four rotations of sample() with N = 4 side by side: lane k of row j holds interval
/// (j + 64 k) mod 256, so a path's four wavelengths are three loads and a lerp in one register
/// (each lane the float operations of atInterval, in the same order).
struct RotatedFour {
    alignas(16) std::array<std::array<float, 4>, kIntervals> start{}, width{}, density{};
};
inline const RotatedFour& rotatedFourTable() {
    static const RotatedFour table = [] {
        const Intervals& t = intervals();
        RotatedFour r;
        for (int j = 0; j < kIntervals; ++j)
            for (int k = 0; k < 4; ++k) {
                const int i = (j + k * (kIntervals / 4)) % kIntervals;
                r.start[j][k] = t.nmFloat[i];
                r.width[j][k] = t.nmFloat[i + 1] - t.nmFloat[i];
                r.density[j][k] = t.densityFloat[i];
            }
        return r;
    }();
    return table;
}
inline void rotatedFour(const Position& p, float* lambda, float* pdf) {
    const RotatedFour& t = rotatedFourTable();
    const auto j = std::size_t(p.interval);
    const simd::Float4 f = simd::splat(float(p.fraction));
    simd::store(lambda, simd::load(t.start[j].data()) + f * simd::load(t.width[j].data()));
    simd::store(pdf, simd::load(t.density[j].data()));
}
}  // namespace visible_wavelengths

template <std::floating_point T, int N = kSpectrumSamples>
class SampledWavelengths {
  public:
    using Spectrum = SampledSpectrum<T, N>;

    /// Hero wavelength from u in [0, 1), the others rotated by k/N. With the visible density
    /// the rotation is done on the intervals: frac(u + k/N) lies in interval
    /// (j + 256 k / N) mod 256 at the same fraction as u in its interval j, since N divides 256
    /// (exact, where u + k/N rounded in float would move the fraction by an ulp).
    static SampledWavelengths sample(double u,
                                     WavelengthSampling method = WavelengthSampling::Visible) {
        SampledWavelengths w;
        if (method == WavelengthSampling::Visible) {
            static_assert(visible_wavelengths::kIntervals % N == 0);
            const visible_wavelengths::Position p = visible_wavelengths::locate(u);
            if constexpr (std::same_as<T, float> && N == 4) {
                visible_wavelengths::rotatedFour(p, w.lambda_.data(), w.pdf_.data());
            } else {
                for (int k = 0; k < N; ++k) {
                    const int j = (p.interval + k * (visible_wavelengths::kIntervals / N)) %
                                  visible_wavelengths::kIntervals;
                    w.lambda_[k] = visible_wavelengths::atInterval(j, T(p.fraction), w.pdf_[k]);
                }
            }
            return w;
        }
        for (int k = 0; k < N; ++k) {
            double uk = u + double(k) / N;
            if (uk >= 1.0) uk -= 1.0;
            w.lambda_[k] = static_cast<T>(kLambdaMin + uk * (kLambdaMax - kLambdaMin));
            w.pdf_[k] = static_cast<T>(1.0 / (kLambdaMax - kLambdaMin));
        }
        return w;
    }

    /// Fixed wavelengths (for `lamina bsdf --wavelengths`, tests): pdf 1 each.
    static SampledWavelengths fixed(const std::array<T, N>& nm) {
        SampledWavelengths w;
        w.lambda_ = nm;
        w.pdf_.fill(T(1));
        return w;
    }

    T operator[](int i) const { return lambda_[i]; }
    T hero() const { return lambda_[0]; }
    Spectrum pdf() const {
        Spectrum s;
        for (int i = 0; i < N; ++i)
            s[i] = pdf_[i];
        return s;
    }

    /// After a dispersive event only the hero wavelength's path is valid: the others get
    /// density 0 (their contributions are dropped) and the hero's estimate is no longer
    /// averaged with them, so its density is divided by N (pbrt-v4 does the same).
    void terminateSecondary() {
        if (secondaryTerminated()) return;
        for (int i = 1; i < N; ++i)
            pdf_[i] = T(0);
        pdf_[0] /= T(N);
    }
    bool secondaryTerminated() const {
        for (int i = 1; i < N; ++i)
            if (pdf_[i] != T(0)) return false;
        return true;
    }

  private:
    std::array<T, N> lambda_{};
    std::array<T, N> pdf_{};
};

}  // namespace lamina
