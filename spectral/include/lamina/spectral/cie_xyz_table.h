// The CIE 1931 colour matching functions divided by the integral of y-bar, resampled at
// every nanometre in float (ResampledSpectrum): spectral mode's film converts a path's four
// wavelengths to XYZ with them. The functions are piecewise linear on 5 nm knots from 360 nm
// (colord-data), so the 1 nm samples reproduce them to float rounding, and one position
// serves all three.
#pragma once

#include <array>

#include "lamina/core/float4.h"
#include "lamina/spectral/resampled_spectrum.h"

namespace lamina {

struct CieXyzTable {
    ResampledSpectrum x, y, z;
    /// x, y, z side by side (and a 0) at each nanometre: one load per wavelength and end.
    std::array<std::array<float, 4>, ResampledSpectrum::kSamples> rows{};

    CieXyzTable(ResampledSpectrum xBar, ResampledSpectrum yBar, ResampledSpectrum zBar);

    /// x-bar, y-bar, z-bar / integral of y-bar: a constant spectrum 1 integrates to Y = 1.
    static const CieXyzTable& normalized();

    /// sum over the lanes k = 0..3, in that order, of w_k (x, y, z)(lambda_k), each of x, y, z
    /// interpolated as ResampledSpectrum::at does: the same floats as the three tables give,
    /// computed in one register for x, y and z together.
    std::array<float, 3> weightedSum(const SampledSpectrum<float, 4>& w,
                                     const ResampledSpectrum::Positions<4>& at) const {
        using namespace simd;
        Float4 sum{};
        for (int k = 0; k < 4; ++k) {
            const auto i = std::size_t(at.i[std::size_t(k)]);
            const Float4 a = load(rows[i].data()), b = load(rows[i + 1].data());
            sum += splat(w[k]) * (a + splat(at.t[std::size_t(k)]) * (b - a));
        }
        return {sum[0], sum[1], sum[2]};
    }
};

}  // namespace lamina
