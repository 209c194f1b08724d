#include <gtest/gtest.h>

#include <type_traits>

#include "lamina/core/spectrum.h"

namespace lamina {
namespace {

TEST(Spectrum, ComponentWiseArithmetic) {
    const Rgbf a(1.0f, 2.0f, 3.0f), b(2.0f, 2.0f, 2.0f);
    EXPECT_EQ(a + b, Rgbf(3.0f, 4.0f, 5.0f));
    EXPECT_EQ(a * b, Rgbf(2.0f, 4.0f, 6.0f));
    EXPECT_EQ(a / b, Rgbf(0.5f, 1.0f, 1.5f));
    EXPECT_EQ(2.0f * a, Rgbf(2.0f, 4.0f, 6.0f));
    EXPECT_EQ(1.0f - a, Rgbf(0.0f, -1.0f, -2.0f));
    EXPECT_EQ(a.maxValue(), 3.0f);
    EXPECT_EQ(a.minValue(), 1.0f);
    EXPECT_FLOAT_EQ(a.average(), 2.0f);
    EXPECT_TRUE(Rgbf(0.0f).isZero());
    EXPECT_TRUE((-a).hasNegative());
}

TEST(Spectrum, SafeDivisionAndFiniteness) {
    const SampledSpectrum<double> a(1.0, 2.0, 3.0, 4.0), b(0.0, 1.0, 0.0, 2.0);
    EXPECT_EQ(safeDiv(a, b), SampledSpectrum<double>(0.0, 2.0, 0.0, 2.0));
    EXPECT_FALSE((a / b).isFinite());
    EXPECT_TRUE(a.isFinite());
    EXPECT_EQ(sqrt(SampledSpectrum<double>(4.0, -1.0, 9.0, 0.0)),
              SampledSpectrum<double>(2.0, 0.0, 3.0, 0.0));
}

TEST(Spectrum, RgbAndSampledAreDistinctTypes) {
    static_assert(!std::is_same_v<Rgb<float>, SampledSpectrum<float, 3>>);
    static_assert(!std::is_convertible_v<Rgb<float>, SampledSpectrum<float, 3>>);
    static_assert(SpectrumType<Rgb<double>>);
    static_assert(SampledSpectrum<float>::kSize == kSpectrumSamples);
    const Rgbd d(Rgbf(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(d, Rgbd(0.5, 0.25, 1.0));
}

TEST(Spectrum, LuminanceOfWhiteIsOne) {
    EXPECT_NEAR(luminance(Rgbd(1.0)), 1.0, 1e-12);
    EXPECT_NEAR(luminance(Rgbd(0.0, 1.0, 0.0)), 0.7152, 1e-12);
}

}  // namespace
}  // namespace lamina
