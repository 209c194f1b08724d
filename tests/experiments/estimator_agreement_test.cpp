// Welch's t-test of estimator_agreement.h on synthetic batches of known distribution: batches
// of two estimators with equal means are rejected per pixel at about the stated alpha and
// agree; a shift of one batch standard deviation is found.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/math.h"
#include "lamina/core/pcg32.h"
#include "lamina/experiments/estimator_agreement.h"

namespace lamina::experiments {
namespace {

constexpr int kSize = 32, kBatches = 16;

/// Batches whose every pixel is mean + sigma * z, z standard normal, independent.
BatchImages normalBatches(double mean, double sigma, int batches, std::uint64_t seed) {
    Pcg32 rng(seed);
    BatchImages images(kSize, kSize);
    for (int k = 0; k < batches; ++k) {
        render::Film film(kSize, kSize, render::FilmSpace::Rec709);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const double z = std::sqrt(-2 * std::log(1 - rng.nextDouble())) *
                                 std::cos(2 * kPi<double> * rng.nextDouble());
                film.addSample(x, y, Rgb<double>(mean + sigma * z), 1.0);
            }
        images.add(film);
    }
    return images;
}

TEST(EstimatorAgreement, EqualMeansAreRejectedAtAboutAlpha) {
    AgreementTest test;
    test.alpha = 0.05;
    test.blockSize = 8;
    const AgreementResult r = testAgreement(normalBatches(1.0, 0.1, kBatches, 1),
                                            normalBatches(1.0, 0.1, kBatches, 2), test);
    ASSERT_EQ(r.pixelsTested, kSize * kSize);
    EXPECT_EQ(r.blocksTested, 16);
    // Rejections ~ Binomial(1024, 0.05): mean 51.2, standard deviation 7.0; four of them.
    const double sd = std::sqrt(test.alpha * (1 - test.alpha) / r.pixelsTested);
    EXPECT_NEAR(r.pixelRejectionRate(), test.alpha, 4 * sd);
    EXPECT_TRUE(r.agree(test.alpha));
    EXPECT_NEAR(r.relativeDifference, 0.0, 4 * r.standardError);
}

TEST(EstimatorAgreement, AShiftOfOneBatchStandardDeviationIsFound) {
    AgreementTest test;
    test.alpha = 0.05;
    const AgreementResult r = testAgreement(normalBatches(1.0, 0.1, kBatches, 3),
                                            normalBatches(1.1, 0.1, kBatches, 4), test);
    // Per pixel t ~ 0.1 / sqrt(2 * 0.1^2 / 16) = 2.8: most pixels reject, every block does.
    EXPECT_GT(r.pixelRejectionRate(), 0.5);
    EXPECT_EQ(r.blocksRejected, r.blocksTested);
    EXPECT_LT(r.meanPValue, 1e-6);
    EXPECT_FALSE(r.agree(test.alpha));
    EXPECT_NEAR(r.relativeDifference, 1.0 / 1.1 - 1.0, 4 * r.standardError);
}

TEST(EstimatorAgreement, AReferenceOfOneBatchIsTestedAgainstItsValue) {
    AgreementTest test;
    const BatchImages exact = normalBatches(1.0, 0.0, 1, 5);
    EXPECT_TRUE(testAgreement(normalBatches(1.0, 0.1, kBatches, 6), exact, test).agree(test.alpha));
    EXPECT_FALSE(
        testAgreement(normalBatches(1.05, 0.1, kBatches, 7), exact, test).agree(test.alpha));
}

/// Batches of `samples` samples per pixel, each sample 1 / p with probability p and 0
/// otherwise (mean 1): rare large values, the light tracer's caustics and glossy highlights.
BatchImages fireflyBatches(int batches, int samples, double p, std::uint64_t seed) {
    Pcg32 rng(seed);
    BatchImages images(kSize, kSize);
    for (int k = 0; k < batches; ++k) {
        render::Film film(kSize, kSize, render::FilmSpace::Rec709);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                for (int s = 0; s < samples; ++s)
                    film.addSample(x, y, Rgb<double>(rng.nextDouble() < p ? 1 / p : 0.0), 1.0);
        images.add(film);
    }
    return images;
}

TEST(PixelTestCalibration, NormalBatchesAreTrusted) {
    const BatchImages a = normalBatches(1.0, 0.1, kBatches, 8),
                      b = normalBatches(2.0, 0.3, kBatches, 9);
    const PixelTestCalibration c = calibratePixelTest(a, b, AgreementTest{}, 64);
    EXPECT_TRUE(c.checked);
    EXPECT_TRUE(c.trustworthy) << c.nullRejectionRate;
    EXPECT_EQ(c.recommendedSpp, 0);
}

TEST(PixelTestCalibration, RareLargeSamplesAgainstASmoothEstimatorAreFlagged) {
    // Both estimate 1 everywhere, yet the per-pixel test rejects far more than alpha: with
    // 8 batches of 4 samples at p = 0.02 most pixels see no large sample at all.
    AgreementTest test;
    const BatchImages smooth = normalBatches(1.0, 0.05, 8, 10),
                      heavy = fireflyBatches(8, 4, 0.02, 11);
    const AgreementResult actual = testAgreement(heavy, smooth, test);
    const PixelTestCalibration c = calibratePixelTest(heavy, smooth, test, 32);
    EXPECT_GT(actual.pixelRejectionRate(), 5 * test.alpha) << "the case to be caught";
    EXPECT_TRUE(c.checked);
    EXPECT_FALSE(c.trustworthy) << c.nullRejectionRate;
    EXPECT_GT(c.nullRejectionRate, 2 * test.alpha);
    // spp x (rate - alpha) / alpha, a multiple of the 8 batches, above 32.
    EXPECT_GT(c.recommendedSpp, 32);
    EXPECT_EQ(c.recommendedSpp % 8, 0);
}

TEST(PixelTestCalibration, NeedsFourBatches) {
    const BatchImages few = normalBatches(1.0, 0.1, 3, 12), other = normalBatches(1.0, 0.1, 3, 13);
    const PixelTestCalibration c = calibratePixelTest(few, other, AgreementTest{}, 24);
    EXPECT_FALSE(c.checked);
    EXPECT_TRUE(c.trustworthy);
}

}  // namespace
}  // namespace lamina::experiments
