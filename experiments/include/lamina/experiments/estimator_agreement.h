// Do two estimators converge to the same image? Each is rendered as K independent batches
// (own seeds, independent sampler), which gives every pixel, every block of pixels and the
// whole image a mean and the variance of that mean with K - 1 degrees of freedom, covariances
// between pixels included (one light path splats into many pixels). Two images are then
// compared by Welch's t-test per pixel and per block (luminance), at significance alpha:
// when the estimators agree, about alpha of the tests reject.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lamina/experiments/kept_renders.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// The luminance of K batch renders of one estimator.
class BatchImages {
  public:
    BatchImages(int width, int height) : width_(width), height_(height) {}
    void add(const render::Film& film);
    /// Adds the batch's Stokes component S_component (0..3) of a polarised render (the film's
    /// Stokes layers; S0 is the image) instead of the image: its luminance, signed.
    void addStokes(const render::Film& film, int component);

    int width() const { return width_; }
    int height() const { return height_; }
    int batches() const { return int(batches_.size()); }
    struct RegionStatistics {
        double mean;            ///< over the batches, of the luminance averaged over the region
        double varianceOfMean;  ///< between-batch variance / K (0 for a single batch)
    };
    /// Statistics of the pixel rectangle [x0, x1) x [y0, y1).
    RegionStatistics region(int x0, int y0, int x1, int y1) const;
    /// A Rec.709 image of the mean over the batches.
    const std::vector<Rgb<double>>& meanImage() const { return meanRgb_; }
    /// The luminance of pixel (x, y) in one batch.
    float value(int batch, int x, int y) const {
        return batches_[std::size_t(batch)][std::size_t(y) * width_ + x];
    }

  private:
    template <typename PixelOf>
    void addPixels(PixelOf&& pixelOf);
    double regionMean(std::size_t batch, int x0, int y0, int x1, int y1) const;
    int width_, height_;
    std::vector<std::vector<float>> batches_;  ///< luminance per batch
    std::vector<Rgb<double>> meanRgb_;
};

struct AgreementTest {
    double alpha = 0.01;
    int blockSize = 8;
};

struct AgreementResult {
    int pixelsTested = 0, pixelsRejected = 0;
    int blocksTested = 0, blocksRejected = 0;
    double meanA = 0, meanB = 0;
    double relativeDifference = 0;  ///< (mean A - mean B) / mean B over the whole image
    double standardError = 0;       ///< of relativeDifference
    std::vector<float> pixelT;      ///< per pixel, 0 where not tested
    std::vector<float> blockT;      ///< per pixel, its block's statistic

    double pixelRejectionRate() const {
        return pixelsTested ? double(pixelsRejected) / pixelsTested : 0.0;
    }
    double blockRejectionRate() const {
        return blocksTested ? double(blocksRejected) / blocksTested : 0.0;
    }
    /// p-value of the whole-image means being equal (Welch's t-test).
    double meanPValue = 1;
    /// p-value of seeing this many rejected blocks (or more) if the estimators agree
    /// (binomial with probability alpha per block).
    double blockRejectionPValue(double alpha) const;
    /// The verdict: neither the number of rejected blocks nor the difference of the image
    /// means is significant at level 0.001.
    bool agree(double alpha) const;
};

/// Whether the per-pixel t-test holds its significance level for these two estimators at
/// this sample count.
///
/// Welch's test assumes that a pixel's batch means are about normal. With heavy-tailed
/// per-sample values (caustics, light tracing of glossy surfaces in view) and few samples they
/// are not: most batches miss the rare large values, so a typical heavy-tailed estimate is
/// low AND its variance estimate small, and against a low-variance estimator the test rejects
/// far more than alpha although both are unbiased (13-15% at alpha 0.01 on the rough glass
/// scene at 32 spp in 8 batches). Two halves of the same estimator would not show it: their
/// skews cancel in the difference. A per-pixel kurtosis or skewness from 8 or 16 batch means
/// is too noisy to decide on. So the test's own false-rejection rate is estimated for the
/// pair at hand by the bootstrap (Efron and Tibshirani 1993, ch. 12, the bootstrap-t): each
/// side's batches are resampled with replacement around their own mean (the null hypothesis
/// made true while keeping each side's distribution), and the per-pixel test is run on
/// `resamples` such pairs; the rate is pooled over all pixels.
///
/// The test is trusted when that rate is at most 2 alpha plus three binomial standard
/// deviations. Otherwise the recommended sample count assumes that the excess rejection
/// (rate - alpha) falls as 1 / (samples): the error of a two-sided t-test under non-normality
/// is of order 1/n (its Edgeworth expansion's 1/sqrt(n) skewness terms cancel between the
/// two tails), so spp x (rate - alpha) / alpha samples bring the excess down to alpha.
struct PixelTestCalibration {
    bool checked = false;          ///< false with fewer than 4 batches on the noisier side
    bool trustworthy = true;       ///< unchecked counts as trusted
    double nullRejectionRate = 0;  ///< the bootstrap estimate of the false-rejection rate
    int recommendedSpp = 0;        ///< when not trustworthy: a multiple of the batch count
};
PixelTestCalibration calibratePixelTest(const BatchImages& a, const BatchImages& b,
                                        const AgreementTest& test, int spp, int resamples = 16,
                                        std::uint64_t seed = 1);

/// Tests A against B. `b` may have a single batch (a reference): its variance is then zero.
AgreementResult testAgreement(const BatchImages& a, const BatchImages& b,
                              const AgreementTest& test);

/// Renders `batches` independent renders of `spp / batches` samples per pixel each (seeds
/// derived from options.seed and the batch index; independent sampler).
BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, const std::function<void(int batch)>& onBatch = {});
/// The same, each batch through `kept` as the render NAME_batchK (kept_renders.h).
BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, KeptRenders& kept, const std::string& name,
                          const std::function<void(int batch)>& onBatch = {});

}  // namespace lamina::experiments
