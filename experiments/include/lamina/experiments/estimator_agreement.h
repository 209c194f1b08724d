// Do two estimators converge to the same image? Each is rendered as K independent batches
// (own seeds, independent sampler), which gives every pixel, every block of pixels and the
// whole image a mean and the variance of that mean with K - 1 degrees of freedom, covariances
// between pixels included (one light path splats into many pixels). Two images are then
// compared by Welch's t-test per pixel and per block (luminance), at significance alpha:
// when the estimators agree, about alpha of the tests reject.
#pragma once

#include <functional>
#include <vector>

#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// The luminance of K batch renders of one estimator.
class BatchImages {
  public:
    BatchImages(int width, int height) : width_(width), height_(height) {}
    void add(const render::Film& film);

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

  private:
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

/// Tests A against B. `b` may have a single batch (a reference): its variance is then zero.
AgreementResult testAgreement(const BatchImages& a, const BatchImages& b,
                              const AgreementTest& test);

/// Renders `batches` independent renders of `spp / batches` samples per pixel each (seeds
/// derived from options.seed and the batch index; independent sampler).
BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, const std::function<void(int batch)>& onBatch = {});

}  // namespace lamina::experiments
