// ResampledSpectrum (spectral/include/lamina/spectral/resampled_spectrum.h) against the
// spectra it stands for, with the accuracy its header states; and the film's colour matching
// table against cieXyz.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lamina/spectral/cie_xyz_table.h"
#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/resampled_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina {
namespace {

/// The largest |resampled / exact - 1| over [360, 830] every 0.01 nm (exact values below
/// `floor` of the curve's maximum compared absolutely, relative to that maximum).
template <typename F>
double worstRelativeError(const ResampledSpectrum& r, F&& exact) {
    double peak = 0.0;
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 0.01)
        peak = std::max(peak, std::abs(exact(nm)));
    double worst = 0.0;
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 0.01) {
        const double e = exact(nm);
        const double scale = std::max(std::abs(e), 1e-3 * peak);
        worst = std::max(worst, std::abs(double(r(float(nm))) - e) / scale);
    }
    return worst;
}

// The CIE functions are piecewise linear on 5 nm knots from 360 nm: the 1 nm resampling is
// the same function, to float rounding (relative to 1e-3 of the peak where they are near 0).
TEST(ResampledSpectrum, ReproducesTheColourMatchingFunctionsToFloatRounding) {
    const CieXyzTable& t = CieXyzTable::normalized();
    const double inverse = 1.0 / cieYIntegral();
    EXPECT_LT(worstRelativeError(t.x, [&](double nm) { return cieXyz(nm).x * inverse; }), 1e-5);
    EXPECT_LT(worstRelativeError(t.y, [&](double nm) { return cieXyz(nm).y * inverse; }), 1e-5);
    EXPECT_LT(worstRelativeError(t.z, [&](double nm) { return cieXyz(nm).z * inverse; }), 1e-5);
}

// Smooth spectra: upsampled RGB illuminants (the sigmoid times D65, whose 5 nm knots the
// 1 nm grid contains; saturated colours curve most) and a 2700 K black body (steepest in the
// blue), within 5e-4 of the value, h^2/8 max|f''| for h = 1 nm.
TEST(ResampledSpectrum, FollowsSmoothEmissionSpectra) {
    for (const Rgb<double>& rgb : {Rgb<double>(1, 1, 1), Rgb<double>(0.9, 0.1, 0.05),
                                   Rgb<double>(0.02, 0.3, 1.0), Rgb<double>(5, 4, 0.5)}) {
        const RgbSpectrum s(rgb, RgbSpectrumKind::Illuminant);
        EXPECT_LT(worstRelativeError(ResampledSpectrum(s), s), 5e-4) << rgb[0] << " " << rgb[1];
    }
    const EmissionSpectrum b = EmissionSpectrum::blackbody(2700, 1.0);
    EXPECT_LT(worstRelativeError(ResampledSpectrum(b), b), 5e-4);
}

// The four wavelengths of a path get what each would get alone; wavelengths outside the range
// take the end values.
TEST(ResampledSpectrum, SampledWavelengthsAndTheEndsOfTheRange) {
    const ResampledSpectrum r([](double nm) { return nm / 100.0; });
    const auto lambda = SampledWavelengths<float>::sample(0.3);
    const SampledSpectrum<float> s = r.at(lambda);
    for (int k = 0; k < kSpectrumSamples; ++k) {
        EXPECT_EQ(s[k], r(lambda[k]));
        EXPECT_NEAR(s[k], lambda[k] / 100.0f, 1e-5f);
    }
    EXPECT_FLOAT_EQ(r(300.0f), 3.6f);
    EXPECT_FLOAT_EQ(r(900.0f), 8.3f);
    EXPECT_FLOAT_EQ(r(830.0f), 8.3f);
}

}  // namespace
}  // namespace lamina
