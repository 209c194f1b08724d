#include "lamina/experiments/estimator_agreement.h"

#include <cmath>

#include "lamina/core/hash.h"
#include "lamina/core/student_t.h"
#include "lamina/spectral/color_space.h"

namespace lamina::experiments {

void BatchImages::add(const render::Film& film) {
    std::vector<float> lum(std::size_t(width_) * height_);
    if (meanRgb_.empty()) meanRgb_.assign(lum.size(), Rgb<double>(0.0));
    const double k = double(batches_.size());
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const std::size_t i = std::size_t(y) * width_ + x;
            const Rgb<double> v = film.pixel(x, y);
            lum[i] = float(luminance(v));
            meanRgb_[i] = (meanRgb_[i] * k + v) / (k + 1.0);
        }
    batches_.push_back(std::move(lum));
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

BatchImages renderBatches(const render::SceneDesc& scene, render::RenderOptions options, int spp,
                          int batches, const std::function<void(int batch)>& onBatch) {
    const int width = options.resolution ? options.resolution->first : scene.film.width;
    const int height = options.resolution ? options.resolution->second : scene.film.height;
    BatchImages images(width, height);
    const std::uint64_t base = options.seed.value_or(scene.settings.seed);
    options.sampler = render::SamplerKind::Independent;
    options.seconds.reset();
    options.spp = std::max(1, spp / batches);
    for (int k = 0; k < batches; ++k) {
        options.seed = hashValues({base, std::uint64_t(k), 0x6261746368ull}) & 0x7fffffffull;
        const render::RenderResult r = render::renderScene(scene, options);
        images.add(*r.film);
        if (onBatch) onBatch(k);
    }
    return images;
}

}  // namespace lamina::experiments
