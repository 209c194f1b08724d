// Error metrics between two images of the same size (the experiments' yardsticks), over the
// RGB channels of every pixel (N = 3 x pixels):
//   mse    = mean((a - b)^2)              rmse = sqrt(mse)
//   relmse = mean((a - b)^2 / (b^2 + eps)), eps = 1e-2 (b is the reference; the epsilon keeps
//            black reference pixels from dominating, as in Rousselle et al. 2011's relMSE)
//   mae    = mean(|a - b|)                max  = max |a - b|
#pragma once

#include "lamina/render/image_output.h"

namespace lamina::render {

inline constexpr double kRelMseEpsilon = 1e-2;

struct ImageMetrics {
    double mse = 0, rmse = 0, relmse = 0, mae = 0, max = 0;
};

/// InputError if the sizes differ.
ImageMetrics compareImages(const RgbImage& a, const RgbImage& reference);

}  // namespace lamina::render
