#include "lamina/render/spectral_film.h"

#include <atomic>
#include <cmath>

namespace lamina::render {

bool SpectralFilmSample::isFinite() const {
    for (const auto& v : value)
        for (const double c : v)
            if (!std::isfinite(c)) return false;
    return true;
}

SpectralFilmSample spectralFilmSample(const SpectralBins& bins,
                                      const SampledWavelengths<float>& lambda,
                                      const SampledSpectrum<float>* components, int count) {
    SpectralFilmSample s;
    const SampledSpectrum<float> pdf = lambda.pdf();
    // 1 / (N width): the average over the path's wavelengths, per nm of the bin.
    const double norm = 1.0 / (double(kSpectrumSamples) * bins.width());
    for (int k = 0; k < kSpectrumSamples; ++k) {
        const auto i = std::size_t(k);
        if (!(pdf[k] > 0.0f)) {
            s.bin[i] = -1;
            continue;
        }
        s.bin[i] = bins.binOf(double(lambda[k]));
        const double w = norm / double(pdf[k]);
        for (int c = 0; c < count; ++c)
            s.value[i][std::size_t(c)] = double(components[c][k]) * w;
    }
    return s;
}

SpectralFilm::SpectralFilm(SpectralBins bins, int components, std::size_t pixels, bool splats)
    : bins_(bins), components_(components), camera_(pixels * valuesPerPixel(), 0.0) {
    if (splats) {
        splatIteration_.assign(camera_.size(), 0.0);
        splatSum_.assign(camera_.size(), 0.0);
    }
}

void SpectralFilm::addSample(std::size_t pixel, const SpectralFilmSample& s, double weight) {
    double* sums = &camera_[pixel * valuesPerPixel()];
    for (std::size_t k = 0; k < s.bin.size(); ++k) {
        if (s.bin[k] < 0) continue;
        for (int c = 0; c < components_; ++c)
            sums[std::size_t(c) * std::size_t(bins_.count) + std::size_t(s.bin[k])] +=
                s.value[k][std::size_t(c)] * weight;
    }
}

void SpectralFilm::addSplat(std::size_t pixel, const SpectralFilmSample& s, double weight) {
    double* sums = &splatIteration_[pixel * valuesPerPixel()];
    for (std::size_t k = 0; k < s.bin.size(); ++k) {
        if (s.bin[k] < 0) continue;
        for (int c = 0; c < components_; ++c)
            std::atomic_ref<double>(
                sums[std::size_t(c) * std::size_t(bins_.count) + std::size_t(s.bin[k])])
                .fetch_add(s.value[k][std::size_t(c)] * weight, std::memory_order_relaxed);
    }
}

void SpectralFilm::endSplatIteration(double scale) {
    for (std::size_t i = 0; i < splatIteration_.size(); ++i) {
        splatSum_[i] += splatIteration_[i] * scale;
        splatIteration_[i] = 0.0;
    }
}

void SpectralFilm::addSums(std::size_t pixel, const double* camera, const double* splat) {
    const std::size_t n = valuesPerPixel(), at = pixel * n;
    for (std::size_t i = 0; i < n; ++i)
        camera_[at + i] += camera[i];
    if (splat && splats())
        for (std::size_t i = 0; i < n; ++i)
            splatSum_[at + i] += splat[i];
}

void SpectralFilm::mean(std::size_t pixel, double weightSum, std::uint64_t splatIterations,
                        double* out) const {
    const std::size_t n = valuesPerPixel(), at = pixel * n;
    for (std::size_t i = 0; i < n; ++i) {
        double v = weightSum > 0 ? camera_[at + i] / weightSum : 0.0;
        if (splats() && splatIterations > 0) v += splatSum_[at + i] / double(splatIterations);
        out[i] = v;
    }
}

}  // namespace lamina::render
