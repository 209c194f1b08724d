// RGB -> spectrum upsampling (Jakob and Hanika 2019) with lamina's own table: round trips,
// bounds, white light, and the unbiasedness of the hero-wavelength estimator.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lamina/core/pcg32.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum_fit.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina {
namespace {

// The linear Rec.709 colour of a reflectance under D65 (or of an emission spectrum alone).
Rgb<double> colorOf(const std::function<double(double)>& spectrum, bool underD65) {
    const Vec3d xyz = integrateAgainstCmf([&](double nm) {
                          return spectrum(nm) * (underD65 ? d65Normalized(nm) : 1.0);
                      }) /
                      cieYIntegral();
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
    return {rgb.x, rgb.y, rgb.z};
}

TEST(RgbToSpectrum, ReflectanceRoundTripOverTheSrgbCube) {
    // 17^3 colours including the cube's faces, edges and corners.
    double worst = 0;
    Rgb<double> worstRgb;
    for (int r = 0; r <= 16; ++r)
        for (int g = 0; g <= 16; ++g)
            for (int b = 0; b <= 16; ++b) {
                const Rgb<double> rgb(r / 16.0, g / 16.0, b / 16.0);
                const RgbSpectrum s(rgb, RgbSpectrumKind::Reflectance);
                const Rgb<double> back = colorOf([&](double nm) { return s(nm); }, true);
                for (int c = 0; c < 3; ++c)
                    if (std::abs(back[c] - rgb[c]) > worst) {
                        worst = std::abs(back[c] - rgb[c]);
                        worstRgb = rgb;
                    }
            }
    EXPECT_LT(worst, 1e-3) << "at " << worstRgb[0] << " " << worstRgb[1] << " " << worstRgb[2];
}

TEST(RgbToSpectrum, ReflectancesStayInTheUnitInterval) {
    Pcg32 rng(5);
    for (int i = 0; i < 2000; ++i) {
        const Rgb<double> rgb(rng.nextDouble(), rng.nextDouble(), rng.nextDouble());
        const RgbSpectrum s(rgb, RgbSpectrumKind::Reflectance);
        for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 5) {
            ASSERT_GE(s(nm), 0.0);
            ASSERT_LE(s(nm), 1.0);
        }
    }
}

// A colour computed from extreme inputs (inf - inf in a texture's arithmetic) may hold a NaN:
// it upsamples as if that component were 0, never indexing out of the table.
TEST(RgbToSpectrum, NotANumberComponentsUpsampleAsZero) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Rgb<double>& rgb :
         {Rgb<double>(nan, 0.5, 0.2), Rgb<double>(0.3, nan, nan), Rgb<double>(nan)}) {
        const RgbSpectrum reflectance(rgb, RgbSpectrumKind::Reflectance);
        Rgb<double> zeroed = rgb;
        for (int c = 0; c < 3; ++c)
            zeroed[c] = std::isnan(rgb[c]) ? 0.0 : rgb[c];
        const RgbSpectrum expected(zeroed, RgbSpectrumKind::Reflectance);
        for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 10) {
            ASSERT_TRUE(std::isfinite(reflectance(nm))) << nm;
            ASSERT_EQ(reflectance(nm), expected(nm)) << nm;
        }
    }
}

TEST(RgbToSpectrum, WhiteLightStaysWhite) {
    const RgbSpectrum white(Rgb<double>(1.0), RgbSpectrumKind::Illuminant);
    const Rgb<double> rgb = colorOf([&](double nm) { return white(nm); }, false);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rgb[c], 1.0, 1e-6);
    // A coloured light keeps its colour and intensity, to the table's round-trip accuracy
    // (1e-3 of the reflectance scale) times the scale 2 max(rgb).
    const RgbSpectrum warm(Rgb<double>(17, 12, 4), RgbSpectrumKind::Illuminant);
    const Rgb<double> w = colorOf([&](double nm) { return warm(nm); }, false);
    EXPECT_NEAR(w[0], 17, 34e-3);
    EXPECT_NEAR(w[1], 12, 34e-3);
    EXPECT_NEAR(w[2], 4, 34e-3);
}

TEST(EmissionSpectrum, NamedSpectraAreNormalisedToTheirLuminance) {
    const Rgb<double> d65 = EmissionSpectrum::illuminant("D65", 1.0).rgb();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(d65[c], 1.0, 1e-6);  // D65 is the white of Rec.709
    const Rgb<double> warm = EmissionSpectrum::blackbody(2700, 3.0).rgb();
    EXPECT_NEAR(luminance(warm), 3.0, 3e-3);  // scale is the luminance (for in-gamut colours)
    EXPECT_GT(warm[0], warm[2]);
    const Rgb<double> a = EmissionSpectrum::illuminant("A", 1.0).rgb();
    EXPECT_GT(a[0], a[1]);
    EXPECT_GT(a[1], a[2]);
}

TEST(RgbToSpectrum, OptimiserConvergesFromAColdStart) {
    const RgbToSpectrumFitter fitter;
    for (const Rgb<double> rgb :
         {Rgb<double>(0.8, 0.3, 0.1), Rgb<double>(0.2, 0.5, 0.9), Rgb<double>(0.5, 0.5, 0.2)}) {
        const SigmoidFit f = fitter.fit(rgb, {0, 0, 0});
        EXPECT_LT(f.residual, 1e-4);
        const Rgb<double> back = fitter.colorOf(f.coefficients);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back[c], rgb[c], 1e-5);
    }
}

TEST(HeroWavelengths, EstimatorOfAReflectanceIsUnbiased) {
    // Mean over wavelength samples of (1/N) sum_i f(l_i) xyz-bar(l_i) / p(l_i) is the XYZ
    // integral. With 200000 estimates the standard error is far below the 2e-3 tolerance
    // (checked: a pdf off by 1% fails).
    const RgbSpectrum s(Rgb<double>(0.7, 0.2, 0.4), RgbSpectrumKind::Reflectance);
    const auto f = [&](double nm) { return s(nm) * d65Normalized(nm); };
    const Vec3d expected = integrateAgainstCmf(f);
    for (auto method : {WavelengthSampling::Visible, WavelengthSampling::Uniform}) {
        Pcg32 rng(11);
        Vec3d sum(0.0);
        const int n = 200000;
        for (int k = 0; k < n; ++k) {
            const auto w = SampledWavelengths<double>::sample(rng.nextDouble(), method);
            for (int i = 0; i < 4; ++i)
                sum += cieXyz(w[i]) * (f(w[i]) / w.pdf()[i] / 4.0);
        }
        const Vec3d mean = sum / double(n);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(mean[c] / expected[c], 1.0, 2e-3) << "component " << c;
    }
}

}  // namespace
}  // namespace lamina
