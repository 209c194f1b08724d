// The wavelengths a spectral path carries: hero-wavelength sampling (Wilkie et al. 2014,
// "Hero Wavelength Spectral Sampling", EGSR). One hero wavelength is drawn at random; the
// other N-1 are its rotations by k/N of the range. With importance sampling the rotation is
// done in primary-sample space (u_k = frac(u + k/N), lambda_k = F^-1(u_k)), so every
// lambda_k has the same marginal density p(lambda) and the N estimates f(lambda_k)/p(lambda_k)
// are stratified over the range.
//
// The importance density follows the shape pbrt-v4 uses for visible wavelengths (Pharr,
// Jakob and Humphreys 2023, "Physically Based Rendering", 4th ed., section 4.6.4),
// p(lambda) proportional to sech^2(a (lambda - mu)) with a = 0.0072 / nm and mu = 538 nm,
// here normalised exactly over lamina's range [360, 830] nm and inverted in closed form:
//   F(lambda) = (tanh(a (lambda - mu)) - t0) / (t1 - t0),  t0,1 = tanh(a (360|830 - mu)).
#pragma once

#include <array>
#include <cmath>

#include "lamina/core/spectrum.h"
#include "lamina/spectral/cie.h"

namespace lamina {

enum class WavelengthSampling { Visible, Uniform };

namespace visible_wavelengths {
inline constexpr double kA = 0.0072;
inline constexpr double kMu = 538.0;
/// tanh(a (360 - mu)) and tanh(a (830 - mu)), computed once: every path samples four
/// wavelengths, and recomputing them cost five tanh per wavelength.
struct RangeTanh {
    double t0, t1;
};
inline const RangeTanh& rangeTanh() {
    static const RangeTanh r{std::tanh(kA * (kLambdaMin - kMu)),
                             std::tanh(kA * (kLambdaMax - kMu))};
    return r;
}
inline double t0() {
    return rangeTanh().t0;
}
inline double t1() {
    return rangeTanh().t1;
}

inline double pdf(double nm) {
    if (nm < kLambdaMin || nm > kLambdaMax) return 0.0;
    return kA / (sqr(std::cosh(kA * (nm - kMu))) * (t1() - t0()));
}
inline double sample(double u) {
    const double t = t0() + u * (t1() - t0());
    return clamp(kMu + std::atanh(t) / kA, kLambdaMin, kLambdaMax);
}
/// sample(u) and its pdf together, in the precision of T: at lambda = F^-1(u),
/// tanh(a (lambda - mu)) is the t the inversion started from, so sech^2 = 1 - t^2 needs no
/// cosh, and atanh(t) = log((1 + t) / (1 - t)) / 2 is one logarithm (in float for the
/// renderer's float wavelengths: double atanh was 8% of a spectral render's profile).
template <std::floating_point T>
T sample(T u, T& pdfOut) {
    const RangeTanh& r = rangeTanh();
    const T t0 = T(r.t0), t1 = T(r.t1);
    const T t = t0 + u * (t1 - t0);
    const T nm = T(kMu) + std::log((T(1) + t) / (T(1) - t)) / T(2 * kA);
    if (!(nm > T(kLambdaMin) && nm < T(kLambdaMax))) {  // rounding at the ends of the range
        const T clamped = clamp(nm, T(kLambdaMin), T(kLambdaMax));
        pdfOut = T(pdf(double(clamped)));
        return clamped;
    }
    pdfOut = T(kA) * (T(1) - t * t) / (t1 - t0);
    return nm;
}
}  // namespace visible_wavelengths

template <std::floating_point T, int N = kSpectrumSamples>
class SampledWavelengths {
  public:
    using Spectrum = SampledSpectrum<T, N>;

    /// Hero wavelength from u in [0, 1), the others rotated by k/N.
    static SampledWavelengths sample(double u,
                                     WavelengthSampling method = WavelengthSampling::Visible) {
        SampledWavelengths w;
        for (int k = 0; k < N; ++k) {
            double uk = u + static_cast<double>(k) / N;
            if (uk >= 1.0) uk -= 1.0;
            if (method == WavelengthSampling::Visible) {
                T p;
                w.lambda_[k] = visible_wavelengths::sample(static_cast<T>(uk), p);
                w.pdf_[k] = p;
            } else {
                w.lambda_[k] = static_cast<T>(kLambdaMin + uk * (kLambdaMax - kLambdaMin));
                w.pdf_[k] = static_cast<T>(1.0 / (kLambdaMax - kLambdaMin));
            }
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
