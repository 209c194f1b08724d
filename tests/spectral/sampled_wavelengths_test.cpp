#include <gtest/gtest.h>

#include <algorithm>

#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina {
namespace {

TEST(SampledWavelengths, VisiblePdfIsNormalisedOverTheRange) {
    double integral = 0.0;
    const double h = 0.01;
    for (double nm = kLambdaMin; nm < kLambdaMax; nm += h)
        integral += h * visible_wavelengths::pdf(nm + 0.5 * h);
    EXPECT_NEAR(integral, 1.0, 1e-6);
    EXPECT_EQ(visible_wavelengths::pdf(350.0), 0.0);
}

TEST(SampledWavelengths, VisibleSamplingInvertsTheCdf) {
    // F(sample(u)) = u: integrate the pdf up to the sampled wavelength.
    for (double u : {0.0, 0.1, 0.37, 0.5, 0.9, 0.999}) {
        const double nm = visible_wavelengths::sample(u);
        double cdf = 0.0;
        const double h = 0.001;
        for (double x = kLambdaMin; x < nm; x += h)
            cdf += h * visible_wavelengths::pdf(x + 0.5 * h);
        EXPECT_NEAR(cdf, u, 2e-4) << "u = " << u;
    }
    EXPECT_NEAR(visible_wavelengths::sample(0.0), kLambdaMin, 1e-9);
}

// The wavelength and pdf the sampler returns together (one logarithm, sech^2 = 1 - t^2) are
// the inverse cdf and the density: to 1e-9 in double, to float precision in float.
TEST(SampledWavelengths, SampledPdfIsTheDensity) {
    for (int i = 0; i <= 1000; ++i) {
        const double u = std::min(i / 1000.0, 1.0 - 1e-12);
        double p = 0;
        const double nm = visible_wavelengths::sample(u, p);
        EXPECT_NEAR(nm, visible_wavelengths::sample(u), 1e-9) << u;
        EXPECT_NEAR(p, visible_wavelengths::pdf(nm), 1e-12 * visible_wavelengths::pdf(nm)) << u;
        float pf = 0;
        const float nmf = visible_wavelengths::sample(float(u), pf);
        EXPECT_NEAR(nmf, visible_wavelengths::sample(double(float(u))), 2e-3) << u;
        EXPECT_NEAR(pf, visible_wavelengths::pdf(nmf), 1e-5 * visible_wavelengths::pdf(nmf)) << u;
    }
}

TEST(SampledWavelengths, HeroRotation) {
    const auto w = SampledWavelengths<double>::sample(0.3, WavelengthSampling::Uniform);
    const double range = kLambdaMax - kLambdaMin;
    EXPECT_NEAR(w[0], kLambdaMin + 0.30 * range, 1e-9);
    EXPECT_NEAR(w[1], kLambdaMin + 0.55 * range, 1e-9);
    EXPECT_NEAR(w[2], kLambdaMin + 0.80 * range, 1e-9);
    EXPECT_NEAR(w[3], kLambdaMin + 0.05 * range, 1e-9);
    EXPECT_NEAR(w.pdf()[2], 1.0 / range, 1e-12);

    const auto v = SampledWavelengths<float>::sample(0.7);
    for (int i = 0; i < kSpectrumSamples; ++i) {
        EXPECT_GE(v[i], kLambdaMin);
        EXPECT_LE(v[i], kLambdaMax);
        EXPECT_NEAR(v.pdf()[i], visible_wavelengths::pdf(v[i]), 1e-6);
    }
}

TEST(SampledWavelengths, TerminateSecondaryKeepsOnlyTheHero) {
    auto w = SampledWavelengths<double>::sample(0.42);
    const double heroPdf = w.pdf()[0];
    EXPECT_FALSE(w.secondaryTerminated());
    w.terminateSecondary();
    EXPECT_TRUE(w.secondaryTerminated());
    EXPECT_NEAR(w.pdf()[0], heroPdf / kSpectrumSamples, 1e-15);
    for (int i = 1; i < kSpectrumSamples; ++i)
        EXPECT_EQ(w.pdf()[i], 0.0);
    w.terminateSecondary();  // idempotent
    EXPECT_NEAR(w.pdf()[0], heroPdf / kSpectrumSamples, 1e-15);
}

}  // namespace
}  // namespace lamina
