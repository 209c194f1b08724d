// Pixel reconstruction filters, applied by filter importance sampling (Ernst et al. 2006;
// pbrt-v4 section 8.8): each camera sample's film position is drawn from the filter's shape
// around the pixel centre and carries the weight f / pdf, so samples never leave their pixel
// and every pixel's value depends on its own samples only (deterministic under threading).
// Filters are separable: f(x, y) = f1(x) f1(y).
//   box             f1 = 1 on [-r, r]                  (r = 0.5: the one-pixel box)
//   gaussian        f1 = exp(-x^2 / (2 s^2)) - exp(-r^2 / (2 s^2)), s = `sigma` (default
//                   r / 3): pbrt-v4's GaussianFilter (radius 1.5, sigma 0.5 by default) and
//                   Mitsuba 3's gaussian (stddev s, radius 4 s) subtract the same tail
//   triangle        f1 = r - |x| (pbrt-v4's TriangleFilter; Mitsuba 3's tent), drawn exactly
//                   by its inverse CDF, so every weight is 1
//   blackman_harris the 4-term Blackman-Harris window over [-r, r] (Harris 1978, Table 1:
//                   a0 = 0.35875, a1 = 0.48829, a2 = 0.14128, a3 = 0.01168)
#pragma once

#include <array>
#include <vector>

#include "lamina/core/math.h"
#include "lamina/core/vector.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

class PixelFilter {
  public:
    explicit PixelFilter(const FilmDesc& film);

    struct Sample {
        Vec2<float> offset;  ///< from the pixel centre, in pixels
        float weight;        ///< f / pdf
    };
    Sample sample(const Vec2<float>& u) const;
    float evaluate1D(float x) const;
    /// The filter normalised to integral 1 at an offset from a pixel centre: the weight with
    /// which a splat at that offset counts for the pixel (light tracing).
    float normalizedWeight(const Vec2<float>& offset) const;
    float radius() const { return radius_; }

  private:
    // Piecewise-constant 1D distribution of f1 over [-r, r].
    float sample1D(float u, float& pdf) const;
    // The triangle's exact inverse CDF.
    float sampleTriangle(float u) const;

    FilterKind kind_;
    float radius_;
    float sigma_ = 0;          ///< gaussian: the standard deviation
    float gaussianFloor_ = 0;  ///< exp(-r^2 / (2 s^2)), what the Gaussian subtracts
    std::vector<float> cdf_;   ///< kBins + 1 entries
    std::vector<float> func_;  ///< kBins entries
    /// guide_[j]: the last bin i with cdf_[i] <= j / kGuide, where the search for a u in
    /// [j / kGuide, (j + 1) / kGuide) starts (a guide table: one or two steps instead of a
    /// binary search over the whole cdf).
    std::vector<int> guide_;
    float integral_ = 1;
};

}  // namespace lamina::render
