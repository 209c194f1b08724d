#include "lamina/experiments/estimator_agreement.h"
#include "lamina/experiments/text_format.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/student_t.h"
#include "lamina/spectral/color_space.h"

namespace lamina::experiments {

template <typename PixelOf>
void BatchImages::addPixels(PixelOf&& pixelOf) {
    std::vector<float> lum(std::size_t(width_) * height_);
    if (meanRgb_.empty()) meanRgb_.assign(lum.size(), Rgb<double>(0.0));
    const double k = double(batches_.size());
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const std::size_t i = std::size_t(y) * width_ + x;
            const Rgb<double> v = pixelOf(x, y);
            lum[i] = float(luminance(v));
            meanRgb_[i] = (meanRgb_[i] * k + v) / (k + 1.0);
        }
    batches_.push_back(std::move(lum));
}

void BatchImages::add(const render::Film& film) {
    addPixels([&](int x, int y) { return film.pixel(x, y); });
}

void BatchImages::addStokes(const render::Film& film, int component) {
    addPixels([&](int x, int y) { return film.stokes(x, y)[std::size_t(component)]; });
}

double BatchImages::regionMean(std::size_t batch, int x0, int y0, int x1, int y1) const {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            sum += double(batches_[batch][std::size_t(y) * width_ + x]);
    return sum / (double(x1 - x0) * double(y1 - y0));
}

BatchImages::RegionStatistics BatchImages::region(int x0, int y0, int x1, int y1) const {
    const std::size_t k = batches_.size();
    if (k == 0) return {0.0, 0.0};
    std::vector<double> means(k);
    double sum = 0;
    for (std::size_t b = 0; b < k; ++b)
        sum += means[b] = regionMean(b, x0, y0, x1, y1);
    const double mean = sum / double(k);
    if (k < 2) return {mean, 0.0};
    double ss = 0;
    for (double m : means)
        ss += sqr(m - mean);
    return {mean, ss / double(k - 1) / double(k)};
}

double AgreementResult::blockRejectionPValue(double alpha) const {
    if (blocksRejected == 0) return 1.0;
    // P(X >= k) for X ~ Binomial(n, alpha) is I_alpha(k, n - k + 1).
    return regularizedIncompleteBeta(double(blocksRejected),
                                     double(blocksTested - blocksRejected + 1), alpha);
}

bool AgreementResult::agree(double alpha) const {
    constexpr double kLevel = 1e-3;
    return blockRejectionPValue(alpha) >= kLevel && meanPValue >= kLevel;
}

namespace {

struct TTest {
    double t = 0;
    bool tested = false, rejected = false;
};

TTest welch(const BatchImages& a, const BatchImages& b, int x0, int y0, int x1, int y1,
            double alpha) {
    const auto [ma, va] = a.region(x0, y0, x1, y1);
    const auto [mb, vb] = b.region(x0, y0, x1, y1);
    TTest r;
    if (!(va + vb > 0.0)) {
        // No variance on either side (black, or constant): testable only by equality.
        r.tested = ma != mb;
        r.rejected = r.tested;
        return r;
    }
    r.tested = true;
    r.t = (ma - mb) / std::sqrt(va + vb);
    const double dof = welchDegreesOfFreedom(va, a.batches(), vb, b.batches());
    r.rejected = studentTTwoSidedPValue(r.t, dof) < alpha;
    return r;
}

}  // namespace

AgreementResult testAgreement(const BatchImages& a, const BatchImages& b,
                              const AgreementTest& test) {
    const int w = a.width(), h = a.height();
    AgreementResult r;
    r.pixelT.assign(std::size_t(w) * h, 0.0f);
    r.blockT.assign(std::size_t(w) * h, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const TTest t = welch(a, b, x, y, x + 1, y + 1, test.alpha);
            r.pixelT[std::size_t(y) * w + x] = float(t.t);
            r.pixelsTested += t.tested;
            r.pixelsRejected += t.rejected;
        }
    const int bs = test.blockSize;
    for (int y0 = 0; y0 + bs <= h; y0 += bs)
        for (int x0 = 0; x0 + bs <= w; x0 += bs) {
            const TTest t = welch(a, b, x0, y0, x0 + bs, y0 + bs, test.alpha);
            for (int y = y0; y < y0 + bs; ++y)
                for (int x = x0; x < x0 + bs; ++x)
                    r.blockT[std::size_t(y) * w + x] = float(t.t);
            r.blocksTested += t.tested;
            r.blocksRejected += t.rejected;
        }
    // The whole image: relative difference of the means, its standard error by the delta
    // method (the two estimates are independent).
    const auto [meanA, va] = a.region(0, 0, w, h);
    const auto [meanB, vb] = b.region(0, 0, w, h);
    r.meanA = meanA;
    r.meanB = meanB;
    if (r.meanB > 0) {
        r.relativeDifference = r.meanA / r.meanB - 1.0;
        r.standardError = std::sqrt(va / sqr(r.meanB) + vb * sqr(r.meanA) / sqr(sqr(r.meanB)));
    }
    if (va + vb > 0)
        r.meanPValue =
            studentTTwoSidedPValue((r.meanA - r.meanB) / std::sqrt(va + vb),
                                   welchDegreesOfFreedom(va, a.batches(), vb, b.batches()));
    else
        r.meanPValue = r.meanA == r.meanB ? 1.0 : 0.0;
    return r;
}

namespace {

/// One side of a pixel's bootstrap: the batch values, their mean.
struct PixelSide {
    std::vector<double> values;
    double mean = 0;
};

PixelSide pixelSide(const BatchImages& images, int x, int y) {
    PixelSide s;
    for (int k = 0; k < images.batches(); ++k)
        s.values.push_back(double(images.value(k, x, y)));
    for (double v : s.values)
        s.mean += v / double(s.values.size());
    return s;
}

/// A resample with replacement, moved to mean 0 (the side's own mean removed): its mean and
/// the variance of that mean.
std::pair<double, double> resample(const PixelSide& side, Pcg32& rng) {
    const std::size_t k = side.values.size();
    if (k < 2) return {0.0, 0.0};  // a reference: exact
    double sum = 0, sumSq = 0;
    for (std::size_t i = 0; i < k; ++i) {
        const double v =
            side.values[std::min(k - 1, std::size_t(rng.nextDouble() * double(k)))] - side.mean;
        sum += v;
        sumSq += v * v;
    }
    const double mean = sum / double(k);
    const double variance = std::max(0.0, (sumSq - double(k) * mean * mean) / double(k - 1));
    return {mean, variance / double(k)};
}

}  // namespace

PixelTestCalibration calibratePixelTest(const BatchImages& a, const BatchImages& b,
                                        const AgreementTest& test, int spp, int resamples,
                                        std::uint64_t seed) {
    PixelTestCalibration c;
    if (std::max(a.batches(), b.batches()) < 4 || std::min(a.batches(), b.batches()) < 1) return c;
    Pcg32 rng(seed);
    std::uint64_t tested = 0, rejected = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const PixelSide sa = pixelSide(a, x, y), sb = pixelSide(b, x, y);
            for (int r = 0; r < resamples; ++r) {
                const auto [ma, va] = resample(sa, rng);
                const auto [mb, vb] = resample(sb, rng);
                if (!(va + vb > 0.0)) continue;  // the test itself leaves these out
                const double t = (ma - mb) / std::sqrt(va + vb);
                const double dof = welchDegreesOfFreedom(va, a.batches(), vb, b.batches());
                ++tested;
                rejected += studentTTwoSidedPValue(t, dof) < test.alpha;
            }
        }
    if (tested == 0) return c;
    c.checked = true;
    c.nullRejectionRate = double(rejected) / double(tested);
    const double alpha = test.alpha;
    // Pixels, not resamples, are the independent units of the estimate.
    const double pixels = double(tested) / resamples;
    c.trustworthy = c.nullRejectionRate <= 2 * alpha + 3 * std::sqrt(alpha * (1 - alpha) / pixels);
    if (!c.trustworthy) {
        const int batches = std::max(a.batches(), b.batches());
        const double factor = (c.nullRejectionRate - alpha) / alpha;
        const double perBatch = std::ceil(std::max(1.0, double(spp) / batches) * factor);
        c.recommendedSpp = int(std::min(perBatch * batches, double(1 << 24)));
    }
    return c;
}

BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, const std::function<void(int batch)>& onBatch) {
    KeptRenders none;
    return renderBatches(scene, std::move(options), spp, batches, none, "", onBatch);
}

BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, KeptRenders& kept, const std::string& name,
                          const std::function<void(int batch)>& onBatch) {
    const int width = options.resolution ? options.resolution->first : scene.film.width;
    const int height = options.resolution ? options.resolution->second : scene.film.height;
    BatchImages images(width, height);
    const std::uint64_t base = options.seed.value_or(scene.settings.seed);
    options.sampler = render::SamplerKind::Independent;
    options.seconds.reset();
    options.spp = std::max(1, spp / batches);
    for (int k = 0; k < batches; ++k) {
        options.seed = hashValues({base, std::uint64_t(k), 0x6261746368ull}) & 0x7fffffffull;
        const render::RenderResult r =
            kept.render(formatText("%s_batch%02d", name.c_str(), k), scene, options, {}, "");
        images.add(*r.film);
        if (onBatch) onBatch(k);
    }
    return images;
}

}  // namespace lamina::experiments
