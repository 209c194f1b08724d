// The film: per pixel, the weighted sum of sample values (linear Rec.709 in RGB mode, CIE XYZ
// in spectral mode), the sum of weights, and the sums a per-pixel variance estimate needs
// (of the luminance Y); optional first-hit AOVs; and a splat layer for estimators that land
// anywhere on the image (light tracing, BDPT's t = 1 strategy). Splats arrive in iterations (one
// light path per pixel each): an iteration's splat image is accumulated with atomic adds, then
// folded into a running mean and sum of squares, so the splat layer has a per-pixel variance
// estimate too (iterations are independent). A sample or splat with NaN, Inf or a negative
// value is never added: it is counted and reported.
// A film may hold a window of a larger image (a crop, `render --crop`): the add* functions take
// coordinates on the whole image and ignore what falls outside the window, every reader takes
// coordinates in the window (0 <= x < width()). Every pixel keeps its own sums and counts
// (PixelSums), so films of disjoint sample ranges or windows add up exactly (`lamina merge`).
// With a spectral film (enableSpectralFilm, `render --spectral-film`) every sample and splat
// also deposits its per-bin spectral radiance (spectral_film.h), passed beside its value.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"
#include "lamina/image/pixel_bounds.h"
#include "lamina/render/film_response.h"
#include "lamina/render/spectral_film.h"

namespace lamina::render {

struct PixelAovs {
    Rgb<double> albedo{0.0};
    Vec3<double> normal{0.0};
    double depth = 0;
};

/// The polarised mode's Stokes layers of a pixel (docs/polarisation.md, "Stokes images"): the
/// weighted sums of its camera samples' S1, S2 and S3, in the film's space, in the image frame.
using StokesSums = std::array<Rgb<double>, 3>;

/// What a pixel accumulates: the camera samples' weighted sums (of the film-space value and of
/// its luminance and squared luminance, for the variance), their weight sum and count, the AOV
/// sums, and the splat layer's sums over its iterations with the number of iterations.
struct PixelSums {
    Rgb<double> sum{0.0};
    double weightSum = 0;
    double ySum = 0, ySqSum = 0, yMax = 0;
    std::uint64_t count = 0;
    PixelAovs aovSum;
    Rgb<double> splatSum{0.0};
    double splatYSum = 0, splatYSqSum = 0;
    std::uint64_t splatCount = 0;
    /// Per channel of linear Rec.709: the weighted sum of the camera samples' squares and the
    /// splat iterations' sum of squares (Variance.R/G/B of merged shards).
    Rgb<double> sqSum{0.0};
    Rgb<double> splatSqSum{0.0};
    /// Adds another film's sums of the same pixel (disjoint samples).
    void add(const PixelSums& o);
};

class Film {
  public:
    Film(int width, int height, FilmSpace space);
    /// The window `window` of a fullWidth x fullHeight image.
    Film(int fullWidth, int fullHeight, const PixelBounds& window, FilmSpace space);
    /// What the film allocates per pixel (render_memory.h estimates from it).
    static constexpr std::size_t bytesPerPixel();

    int width() const { return width_; }
    int height() const { return height_; }
    /// The whole image the window belongs to (width() x height() without a crop).
    int fullWidth() const { return fullWidth_; }
    int fullHeight() const { return fullHeight_; }
    const PixelBounds& window() const { return window_; }
    FilmSpace space() const { return space_; }

    /// The sensor every sample and splat goes through (a film starts with the identity).
    void setResponse(const FilmResponse& response) { response_ = response; }
    const FilmResponse& response() const { return response_; }

    /// Adds a camera sample to pixel (x, y) of the whole image, through the response, and with
    /// a spectral film its deposits `spectral` (which it needs then). Returns false if it is
    /// outside the window, or if rejected (and counts it): then nothing is added.
    bool addSample(int x, int y, const Rgb<double>& value, double weight,
                   const SpectralFilmSample* spectral = nullptr);
    void addAovs(int x, int y, const PixelAovs& aovs);

    /// Gives the film Stokes layers (the polarised mode): S1..S3 beside the image, which is S0.
    void enableStokes() {
        stokes_.assign(pixels_.size(), StokesSums{});
        stokesSplatIteration_.assign(pixels_.size(), StokesSums{});
        stokesSplatSum_.assign(pixels_.size(), StokesSums{});
    }
    bool hasStokes() const { return !stokes_.empty(); }
    /// Adds a polarised camera sample: its Stokes vector S0..S3 in the film's space (S0 is the
    /// sample's value, as addSample takes it; S1..S3 may be negative). All four go through the
    /// response as one (FilmResponse::applyAlongside). Returns false, and adds nothing, if it
    /// is outside the window or rejected (and counts it). Needs enableStokes().
    bool addPolarisedSample(int x, int y, const std::array<Rgb<double>, 4>& stokes, double weight,
                            const SpectralFilmSample* spectral = nullptr);
    /// The same for a splat (light tracing, BDPT), as addSplat takes it. Thread-safe.
    bool addPolarisedSplat(int x, int y, const std::array<Rgb<double>, 4>& stokes, double weight,
                           const SpectralFilmSample* spectral = nullptr);
    /// The pixel's Stokes vector in linear Rec.709 (each component converted as the image is):
    /// S0 is pixel(x, y). Needs enableStokes().
    std::array<Rgb<double>, 4> stokes(int x, int y) const;
    /// The pixel's raw Stokes sums of S1..S3 in the film's space (shard files): the camera
    /// samples' weighted sums and the finished splat iterations' sums. Needs enableStokes().
    const StokesSums& stokesCameraSums(int x, int y) const {
        return stokes_[std::size_t(y) * width_ + std::size_t(x)];
    }
    const StokesSums& stokesSplatSums(int x, int y) const {
        return stokesSplatSum_[std::size_t(y) * width_ + std::size_t(x)];
    }
    /// Adds another film's Stokes sums to pixel (x, y) of the whole image, as addSums adds
    /// the image's; ignored outside the window. Needs enableStokes().
    void addStokesSums(int x, int y, const StokesSums& camera, const StokesSums& splat);

    /// Gives the film a spectral film of `components` Stokes components (1 or 4) per bin, with
    /// a splat layer if the render splats (spectral_film.h).
    void enableSpectralFilm(SpectralBins bins, int components, bool splats) {
        spectral_ = std::make_unique<SpectralFilm>(bins, components, pixels_.size(), splats);
    }
    /// Null without one.
    const SpectralFilm* spectralFilm() const { return spectral_.get(); }
    /// Pixel (x, y)'s mean spectral radiance per bin, [component][bin]: valuesPerPixel()
    /// doubles into `out`. Needs a spectral film.
    void spectralMean(int x, int y, double* out) const {
        const Pixel& p = at(x, y);
        spectral_->mean(std::size_t(y) * width_ + std::size_t(x), p.weightSum, p.splatCount, out);
    }
    /// Adds another film's spectral sums to pixel (x, y) of the whole image (`splat` may be
    /// null); ignored outside the window. Needs a spectral film.
    void addSpectralSums(int x, int y, const double* camera, const double* splat) {
        if (!window_.contains(x, y)) return;
        spectral_->addSums(std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0),
                           camera, splat);
    }
    /// Adds a value times `weight` (its filter weight: the response sees the value before it)
    /// to pixel (x, y) of the whole image in the current splat iteration (thread-safe).
    /// Returns false if it is outside the window, or if rejected (and counts it).
    bool addSplat(int x, int y, const Rgb<double>& value, double weight = 1.0,
                  const SpectralFilmSample* spectral = nullptr);
    /// Ends a splat iteration: its image times `scale` becomes one more sample of the splat
    /// layer's per-pixel mean and variance. Not thread-safe (call between iterations).
    void endSplatIteration(double scale);
    int splatIterations() const { return splatIterations_; }

    /// Linear Rec.709 value of a pixel: the camera samples' weighted mean plus the splat
    /// layer's mean.
    Rgb<double> pixel(int x, int y) const;
    /// The variance of the pixel's mean luminance: sample variance / n of the camera samples
    /// plus that of the splat iterations (the two are independent but for the one light path
    /// BDPT traces for the pixel's own sample, whose covariance this neglects).
    double varianceOfMean(int x, int y) const;
    /// The same per channel of linear Rec.709 (Variance.R/G/B).
    Rgb<double> varianceOfMeanRgb(int x, int y) const;
    PixelAovs aovs(int x, int y) const;
    std::uint64_t samples(int x, int y) const { return at(x, y).count; }
    /// The pixel's raw sums (shard files).
    const PixelSums& sums(int x, int y) const { return at(x, y); }
    /// Adds another film's sums to pixel (x, y) of the whole image (`lamina merge`); ignored
    /// outside the window.
    void addSums(int x, int y, const PixelSums& sums) {
        if (window_.contains(x, y)) at(x - window_.x0, y - window_.y0).add(sums);
    }

    std::uint64_t rejectedSamples() const { return rejected_.load(); }
    /// Counts `n` samples rejected elsewhere: a film read back from a shard file takes its count
    /// from the file's metadata.
    void addRejectedSamples(std::uint64_t n) { rejected_.fetch_add(n); }
    /// The largest luminance (Y) of any camera sample added (fireflies).
    double largestSampleLuminance() const;

  private:
    using Pixel = PixelSums;
    const Pixel& at(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
    Pixel& at(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
    Rgb<double> toRec709(const Rgb<double>& v) const;
    bool accumulate(int x, int y, const Rgb<double>& value, double weight);
    /// addSample without the spectral film.
    bool addValue(int x, int y, const Rgb<double>& value, double weight);
    std::size_t windowIndex(int x, int y) const {
        return std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0);
    }
    /// Whether S1..S3 are finite; counts a rejection if not (S0 is checked as a sample's value).
    bool polarisationFinite(const std::array<Rgb<double>, 4>& stokes);

    int width_, height_;
    int fullWidth_, fullHeight_;
    PixelBounds window_;
    FilmSpace space_;
    FilmResponse response_;
    Mat3<double> xyzToRec709_;  ///< looked up once: every sample's squares are taken in Rec.709
    std::vector<Pixel> pixels_;
    std::vector<Rgb<double>> splatIteration_;
    /// per pixel, empty unless enableStokes(): the camera samples' sums, the current splat
    /// iteration's and the sum of the finished iterations'
    std::vector<StokesSums> stokes_, stokesSplatIteration_, stokesSplatSum_;
    std::unique_ptr<SpectralFilm> spectral_;  ///< null unless enableSpectralFilm()
    int splatIterations_ = 0;
    std::atomic<std::uint64_t> rejected_{0};
};

constexpr std::size_t Film::bytesPerPixel() {
    return sizeof(Pixel) + sizeof(Rgb<double>);
}

}  // namespace lamina::render
