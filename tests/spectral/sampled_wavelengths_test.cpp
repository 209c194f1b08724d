#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "lamina/core/math.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina {
namespace {

TEST(SampledWavelengths, VisiblePdfIsNormalisedOverTheRange) {
    double integral = 0.0;
    const double h = 0.01;
    for (double nm = kLambdaMin; nm < kLambdaMax; nm += h)
        integral += h * visible_wavelengths::pdf(nm + 0.5 * h);
    // The midpoint rule errs by up to h times a jump at each of the 255 interval ends.
    EXPECT_NEAR(integral, 1.0, 1e-5);
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

// The wavelength and pdf the sampler returns together are the inverse cdf and the density,
// in double; in float the wavelength agrees to 2e-3 nm and the density is the same interval's.
TEST(SampledWavelengths, SampledPdfIsTheDensity) {
    for (int i = 0; i <= 1000; ++i) {
        const double u = std::min(i / 1000.0, 1.0 - 1e-12);
        double p = 0;
        const double nm = visible_wavelengths::sample(u, p);
        EXPECT_NEAR(nm, visible_wavelengths::sample(u), 1e-9) << u;
        EXPECT_NEAR(p, visible_wavelengths::pdf(nm), 1e-12 * visible_wavelengths::pdf(nm)) << u;
        float pf = 0;
        const float nmf = visible_wavelengths::sample(float(u), pf);
        double pd = 0;
        EXPECT_NEAR(nmf, visible_wavelengths::sample(double(float(u)), pd), 2e-3) << u;
        EXPECT_NEAR(pf, pd, 1e-6 * pd) << u;
    }
}

// The piecewise-constant density stays close to the sech^2 shape it approximates (the
// closed form, normalised over the range), as sampled_wavelengths.h says: within 2% over
// 400-700 nm and 12% over the whole range (checked every 0.01 nm), intervals 0.99 to 15.4 nm
// wide, and probability 1/256 in each.
TEST(SampledWavelengths, VisibleDensityFollowsTheSech2Shape) {
    using namespace visible_wavelengths;
    const double t0 = std::tanh(kA * (kLambdaMin - kMu)), t1 = std::tanh(kA * (kLambdaMax - kMu));
    double worstVisible = 0.0, worst = 0.0;
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 0.01) {
        const double sech2 = kA / (sqr(std::cosh(kA * (nm - kMu))) * (t1 - t0));
        const double deviation = std::abs(pdf(nm) / sech2 - 1.0);
        worst = std::max(worst, deviation);
        if (nm >= 400.0 && nm <= 700.0) worstVisible = std::max(worstVisible, deviation);
    }
    EXPECT_LT(worstVisible, 0.02);
    EXPECT_LT(worst, 0.12);
    const Intervals& t = intervals();
    for (int j = 0; j < kIntervals; ++j) {
        const double width = t.nm[j + 1] - t.nm[j];
        EXPECT_GT(width, 0.99) << j;
        EXPECT_LT(width, 15.4) << j;
        EXPECT_NEAR(t.density[j] * width, 1.0 / kIntervals, 1e-15) << j;
    }
    EXPECT_EQ(t.nm.front(), kLambdaMin);
    EXPECT_EQ(t.nm.back(), kLambdaMax);
}

// The four lanes of a float path (drawn in one register from the rotated tables) are the
// definition in sampled_wavelengths.h bit for bit: u_k = frac(u + k/4) computed exactly (in
// double, where u + k/4 is exact for a float u), then interval floor(256 u_k) and the float
// lerp within it. Random u, the ends of the range and u at and next to interval edges.
TEST(SampledWavelengths, FourLanesAreTheScalarDefinitionBitForBit) {
    using namespace visible_wavelengths;
    const Intervals& t = intervals();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> us = {0.0f, 0.25f, 0.5f, 0.75f, std::nextafter(1.0f, 0.0f)};
    for (int j = 1; j < kIntervals; ++j) {
        const float edge = float(j) / kIntervals;
        us.insert(us.end(), {edge, std::nextafter(edge, 0.0f), std::nextafter(edge, 1.0f)});
    }
    for (int n = 0; n < 100000; ++n)
        us.push_back(std::min(uniform(rng), std::nextafter(1.0f, 0.0f)));
    for (const float u : us) {
        const auto w = SampledWavelengths<float>::sample(double(u));
        const SampledSpectrum<float> pdf = w.pdf();
        for (int k = 0; k < 4; ++k) {
            double uk = double(u) + 0.25 * k;
            if (uk >= 1.0) uk -= 1.0;
            const double x = uk * kIntervals;
            const int j = int(x);
            const float f = float(x - j);
            const float expected = t.nmFloat[j] + f * (t.nmFloat[j + 1] - t.nmFloat[j]);
            ASSERT_EQ(w[k], expected) << u << " lane " << k;
            ASSERT_EQ(pdf[k], t.densityFloat[j]) << u << " lane " << k;
        }
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
