#include "lamina/spectral/fringe_colors.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/math.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina {

const FringeColors& FringeColors::rec709() {
    static const FringeColors table;
    return table;
}

FringeColors::FringeColors() {
    // The integral in wavenumber nu = 1 / lambda, where exp(2 pi i x nu) oscillates evenly:
    // s_c(lambda) d lambda = s_c(1 / nu) / nu^2 d nu, by the trapezoidal rule on an even grid.
    // 2048 steps over 1/830..1/360 nm^-1 turn the phase by 0.2 rad per step at the largest x
    // tabulated, where the transform is below 1e-3 anyway.
    constexpr int kSteps = 2048;
    const double nuMin = 1.0 / kLambdaMax, nuMax = 1.0 / kLambdaMin;
    const double h = (nuMax - nuMin) / kSteps;
    const Mat3<double>& toRgb = RgbColorSpace::rec709().xyzToRgb();
    std::vector<double> nu(kSteps + 1);
    std::array<std::vector<double>, 3> weight;
    for (auto& w : weight)
        w.assign(kSteps + 1, 0.0);
    for (int k = 0; k <= kSteps; ++k) {
        nu[k] = nuMin + h * k;
        const double nm = 1.0 / nu[k];
        const Vec3d rgb = toRgb * (cieXyz(nm) * d65Normalized(nm));
        const double w = (k == 0 || k == kSteps ? 0.5 : 1.0) * h * sqr(nm);
        for (int c = 0; c < 3; ++c)
            weight[c][k] = rgb[c] * w;
    }
    const int n = int(kMaxPathDifference / kStep) + 1;
    for (int c = 0; c < 3; ++c) {
        // Normalised to an integral of exactly 1, so that a film of thickness 0 gives the
        // bare interface's reflectance exactly (Rec.709's white is D65: the sums differ from
        // 1 only by the quadrature).
        // The channel's centre: the mean wavenumber of its positive lobe (Rec.709 red's
        // sensitivity is negative in the blue).
        double total = 0, first = 0, positive = 0;
        for (int k = 0; k <= kSteps; ++k) {
            total += weight[c][k];
            first += std::max(0.0, weight[c][k]) * nu[k];
            positive += std::max(0.0, weight[c][k]);
        }
        for (double& w : weight[c])
            w /= total;
        meanWavenumber_[c] = first / positive;
        envelope_[c].resize(n);
        for (int j = 0; j < n; ++j) {
            const double x = kStep * j;
            // exp(2 pi i x (nu_k - nu_c)) by a turn per step (double: its rounding stays near
            // 1e-13 over the grid).
            const std::complex<double> turn = std::polar(1.0, 2.0 * kPi<double> * x * h);
            std::complex<double> phase =
                std::polar(1.0, 2.0 * kPi<double> * x * (nuMin - meanWavenumber_[c]));
            std::complex<double> sum = 0;
            for (int k = 0; k <= kSteps; ++k) {
                sum += weight[c][k] * phase;
                phase *= turn;
            }
            envelope_[c][j] = sum;
        }
    }
}

namespace {

std::complex<double> interpolated(const std::vector<std::complex<double>>& e, double x) {
    const double f = x / FringeColors::kStep;
    const int j = std::min(int(f), int(e.size()) - 2);
    const double a = f - j;
    return e[j] * (1.0 - a) + e[j + 1] * a;
}

}  // namespace

std::complex<double> FringeColors::operator()(int channel, double pathDifferenceNm) const {
    const double x = std::max(0.0, pathDifferenceNm);
    if (!(x < kMaxPathDifference)) return 0.0;
    return interpolated(envelope_[channel], x) *
           std::polar(1.0, 2.0 * kPi<double> * x * meanWavenumber_[channel]);
}

void FringeColors::atMultiples(int channel, double pathDifferenceNm, int count,
                               std::complex<double>* out) const {
    const double x = std::max(0.0, pathDifferenceNm);
    const std::complex<double> turn =
        std::polar(1.0, 2.0 * kPi<double> * x * meanWavenumber_[channel]);
    std::complex<double> carrier = 1.0;
    for (int m = 1; m <= count; ++m) {
        carrier *= turn;
        out[m - 1] = m * x < kMaxPathDifference ? interpolated(envelope_[channel], m * x) * carrier
                                                : std::complex<double>(0.0);
    }
}

}  // namespace lamina
