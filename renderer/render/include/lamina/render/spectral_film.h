// The spectral film (`render --spectral-film N`): beside the image, each pixel's mean spectral
// radiance in N equal bins over the range the spectral mode samples its wavelengths from,
// [360, 830] nm (kLambdaMin, kLambdaMax): S0 alone in the spectral mode, S0..S3 in the image
// frame of the Stokes layers in the polarised mode (docs/scene-format.md, "Spectral film").
//
// The estimator. A path carries four hero wavelengths lambda_k, each of them alone a sample of
// the range with the density p(lambda) (sampled_wavelengths.h), and the image's XYZ is
// 1/4 sum_k L(lambda_k) cmf(lambda_k) / p(lambda_k) (render_mode.h). The same sample gives bin b
//     1/4 sum_k [lambda_k in b] L(lambda_k) / (p(lambda_k) width),
// whose expectation is 1/width times the integral of L over the bin: its mean. After a
// dispersive event only the hero is left, with density p / 4 (terminateSecondary), and the same
// expression stays unbiased. So width x sum over the bins of a bin's value times the bin's mean
// of the colour matching functions is the image's XYZ, up to how much L varies within a bin.
//
// What a pixel keeps mirrors the image's sums (film.h): the camera samples' weighted sums,
// normalised by the pixel's weight sum, and the splat layer's sums over its iterations,
// normalised by their number. Nothing here is allocated or run when the option is off.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina::render {

/// N equal bins over [kLambdaMin, kLambdaMax] nm.
struct SpectralBins {
    int count = 0;

    double width() const { return (kLambdaMax - kLambdaMin) / count; }
    double start(int bin) const { return kLambdaMin + bin * width(); }
    double centre(int bin) const { return kLambdaMin + (bin + 0.5) * width(); }
    /// The bin of a wavelength; kLambdaMax belongs to the last.
    int binOf(double nm) const {
        const int b = int((nm - kLambdaMin) / width());
        return b < 0 ? 0 : (b >= count ? count - 1 : b);
    }
};

/// What one camera sample or splat gives the spectral film: for each of the path's wavelengths
/// its bin (-1 for a wavelength of density 0, dropped by dispersion) and its S0..S3 (S0 alone
/// outside the polarised mode) as an estimate of that bin's mean (the estimator above), before
/// the sample's filter weight and the sensor's scale.
struct SpectralFilmSample {
    std::array<int, kSpectrumSamples> bin{};
    std::array<std::array<double, 4>, kSpectrumSamples> value{};

    bool isFinite() const;
};

/// The deposits of a path whose Stokes components in the image frame (S0 alone, or S0..S3)
/// are `components` at its wavelengths `lambda`.
SpectralFilmSample spectralFilmSample(const SpectralBins& bins,
                                      const SampledWavelengths<float>& lambda,
                                      const SampledSpectrum<float>* components, int count);

/// The per-pixel sums, [component][bin] for each pixel.
class SpectralFilm {
  public:
    /// `splats`: the render splats (light tracing, BDPT), so the splat layer is kept too.
    SpectralFilm(SpectralBins bins, int components, std::size_t pixels, bool splats);

    const SpectralBins& bins() const { return bins_; }
    int components() const { return components_; }
    bool splats() const { return !splatSum_.empty(); }
    std::size_t valuesPerPixel() const { return std::size_t(bins_.count) * components_; }

    /// Adds a sample's deposits times `weight` (its filter weight times the sensor's scale) to
    /// the camera sums of pixel `pixel`.
    void addSample(std::size_t pixel, const SpectralFilmSample& s, double weight);
    /// The same into the current splat iteration (thread-safe). Needs splats().
    void addSplat(std::size_t pixel, const SpectralFilmSample& s, double weight);
    /// Folds the current splat iteration, times `scale`, into the splat sums.
    void endSplatIteration(double scale);

    /// The raw sums of a pixel (shard files): valuesPerPixel() each; the splat sums are null
    /// without splats().
    const double* cameraSums(std::size_t pixel) const { return &camera_[pixel * valuesPerPixel()]; }
    const double* splatSums(std::size_t pixel) const {
        return splats() ? &splatSum_[pixel * valuesPerPixel()] : nullptr;
    }
    /// Adds another film's sums of the same pixel (`splat` may be null).
    void addSums(std::size_t pixel, const double* camera, const double* splat);

    /// The pixel's mean spectral radiance, [component][bin] into `out`: the camera sums over
    /// the pixel's weight sum plus the splat sums over the number of splat iterations.
    void mean(std::size_t pixel, double weightSum, std::uint64_t splatIterations,
              double* out) const;

  private:
    SpectralBins bins_;
    int components_;
    std::vector<double> camera_, splatIteration_, splatSum_;
};

}  // namespace lamina::render
