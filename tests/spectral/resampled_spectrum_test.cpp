// ResampledSpectrum (spectral/include/lamina/spectral/resampled_spectrum.h) against the
// spectra it stands for, with the accuracy its header states; and the film's colour matching
// table against cieXyz.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

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

// A path's table positions, found in four lanes at once, are locate() of each wavelength, and
// the spectrum at them is operator() of each, bit for bit (inside the range and beyond its
// ends, where the lanes clamp as the scalar code does).
TEST(ResampledSpectrum, FourLanePositionsAreTheScalarOnes) {
    const ResampledSpectrum r([](double nm) { return std::sin(nm / 37.0) + 1.5; });
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> nm(300.0f, 900.0f);
    std::vector<std::array<float, 4>> cases = {
        {float(kLambdaMin), float(kLambdaMax), 829.999f, 360.001f},
        {300.0f, 900.0f, 361.0f, 829.0f}};
    for (int n = 0; n < 50000; ++n)
        cases.push_back({nm(rng), nm(rng), nm(rng), nm(rng)});
    for (const auto& c : cases) {
        const auto lambda = SampledWavelengths<float>::fixed(c);
        const ResampledSpectrum::Positions<4> p = ResampledSpectrum::locate(lambda);
        const SampledSpectrum<float> s = r.at(p);
        for (int k = 0; k < 4; ++k) {
            const ResampledSpectrum::Position q = ResampledSpectrum::locate(c[std::size_t(k)]);
            ASSERT_EQ(p.i[std::size_t(k)], q.i) << c[std::size_t(k)];
            ASSERT_EQ(p.t[std::size_t(k)], q.t) << c[std::size_t(k)];
            ASSERT_EQ(s[k], r(c[std::size_t(k)])) << c[std::size_t(k)];
        }
    }
}

// The film's XYZ sum in one register is the scalar sum over the lanes, in lane order, of
// w_k times each table at lambda_k, bit for bit.
TEST(ResampledSpectrum, ColourMatchingSumIsTheScalarSumBitForBit) {
    const CieXyzTable& t = CieXyzTable::normalized();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f), weight(-2.0f, 50.0f);
    for (int n = 0; n < 50000; ++n) {
        const auto lambda = SampledWavelengths<float>::sample(double(u(rng)));
        SampledSpectrum<float> w;
        for (int k = 0; k < 4; ++k)
            w[k] = n % 7 == 0 && k == 2 ? 0.0f : weight(rng);
        const std::array<float, 3> sum = t.weightedSum(w, ResampledSpectrum::locate(lambda));
        float x = 0.0f, y = 0.0f, z = 0.0f;
        for (int k = 0; k < 4; ++k) {
            const ResampledSpectrum::Position p = ResampledSpectrum::locate(lambda[k]);
            x += w[k] * t.x.at(p);
            y += w[k] * t.y.at(p);
            z += w[k] * t.z.at(p);
        }
        ASSERT_EQ(sum[0], x) << n;
        ASSERT_EQ(sum[1], y) << n;
        ASSERT_EQ(sum[2], z) << n;
    }
}

}  // namespace
}  // namespace lamina
