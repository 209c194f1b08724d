#include "lamina/integrators/strategy_images.h"

#include "lamina/integrators/splat.h"

namespace lamina::render {

StrategyImages::StrategyImages(int width, int height)
    : width_(width), height_(height), weightSums_(std::size_t(width) * height, 0.0) {
    for (int depth = 0; depth <= kMaxDepth; ++depth)
        for (int t = 1; t <= depth + 2; ++t)
            if (!(depth == 0 && t == 1)) strategies_.push_back({depth + 2 - t, t});
    for (auto& b : buffers_)
        b.resize(2 * strategies_.size());
    for (auto& b : buffers_[0])
        b.assign(std::size_t(width) * height, Rgb<double>(0.0));
    for (auto& b : buffers_[1])
        b.assign(std::size_t(width) * height, Rgb<double>(0.0));
}

int StrategyImages::slot(int s, int t) const {
    for (std::size_t i = 0; i < strategies_.size(); ++i)
        if (strategies_[i].first == s && strategies_[i].second == t) return int(i);
    return -1;
}

void StrategyImages::splatFiltered(int slot, const PixelFilter& filter, const Vec2<float>& raster,
                                   const Rgb<double>& weighted, const Rgb<double>& unweighted) {
    forEachFilteredPixel(filter, raster, width_, height_, [&](int x, int y, double w) {
        addSplat(slot, x, y, weighted * w, unweighted * w);
    });
}

std::vector<Rgb<double>> StrategyImages::image(int slot, bool weighted, double particles) const {
    std::vector<Rgb<double>> out(std::size_t(width_) * height_);
    const int b = 2 * slot + (weighted ? 0 : 1);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double w = weightSums_[i];
        out[i] = (w > 0 ? buffers_[0][std::size_t(b)][i] / w : Rgb<double>(0.0)) +
                 buffers_[1][std::size_t(b)][i] / particles;
    }
    return out;
}

}  // namespace lamina::render
