// The film: per pixel, the weighted sum of sample values (linear Rec.709 in RGB mode, CIE XYZ
// in spectral mode), the sum of weights, and the sums a per-pixel variance estimate needs
// (of the luminance Y); optional first-hit AOVs; a splat buffer for estimators that land
// anywhere on the image (light tracing). A sample with NaN, Inf or a negative value is never
// added: it is counted and reported.
#pragma once

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina::render {

enum class FilmSpace { Rec709, Xyz };

struct PixelAovs {
    Rgb<double> albedo{0.0};
    Vec3<double> normal{0.0};
    double depth = 0;
};

class Film {
  public:
    Film(int width, int height, FilmSpace space);

    int width() const { return width_; }
    int height() const { return height_; }
    FilmSpace space() const { return space_; }

    /// Adds a camera sample to pixel (x, y). Returns false (and counts it) if rejected.
    bool addSample(int x, int y, const Rgb<double>& value, double weight);
    void addAovs(int x, int y, const PixelAovs& aovs);
    /// Adds to the splat buffer at a continuous film position (thread-safe).
    void addSplat(float x, float y, const Rgb<double>& value);

    /// Linear Rec.709 value of a pixel: weighted mean plus splats / samplesPerPixel.
    Rgb<double> pixel(int x, int y, double splatScale = 0.0) const;
    /// The variance of the pixel's mean luminance (sample variance / n).
    double varianceOfMean(int x, int y) const;
    PixelAovs aovs(int x, int y) const;
    std::uint64_t samples(int x, int y) const { return at(x, y).count; }

    std::uint64_t rejectedSamples() const { return rejected_.load(); }

  private:
    struct Pixel {
        Rgb<double> sum{0.0};
        double weightSum = 0;
        double ySum = 0, ySqSum = 0;
        std::uint64_t count = 0;
        PixelAovs aovSum;
    };
    const Pixel& at(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
    Pixel& at(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
    Rgb<double> toRec709(const Rgb<double>& v) const;

    int width_, height_;
    FilmSpace space_;
    std::vector<Pixel> pixels_;
    std::vector<Rgb<double>> splats_;
    std::mutex splatMutex_;
    std::atomic<std::uint64_t> rejected_{0};
};

}  // namespace lamina::render
