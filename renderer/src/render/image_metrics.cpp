#include "lamina/render/image_metrics.h"

#include <cmath>

#include "lamina/core/error.h"

namespace lamina::render {

ImageMetrics compareImages(const RgbImage& a, const RgbImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw InputError("the images differ in size: " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    ImageMetrics m;
    const std::size_t n = a.pixels.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        m.mse += d * d;
        m.relmse += d * d / (double(b.pixels[i]) * double(b.pixels[i]) + kRelMseEpsilon);
        m.mae += std::abs(d);
        m.max = std::max(m.max, std::abs(d));
    }
    if (n > 0) {
        m.mse /= double(n);
        m.relmse /= double(n);
        m.mae /= double(n);
    }
    m.rmse = std::sqrt(m.mse);
    return m;
}

}  // namespace lamina::render
