// Per-(s, t) images of BDPT for study (lamina render --strategies): every strategy's
// contribution with and without its MIS weight, up to a path depth. Camera-side contributions
// (t >= 2) are kept per pixel with the camera samples' filter weights; splats (t = 1) as
// sums over light paths, so a strategy's image is the same estimate the film makes.
#pragma once

#include <array>
#include <atomic>
#include <utility>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina::render {

class PixelFilter;

class StrategyImages {
  public:
    static constexpr int kMaxDepth = 4;  ///< s + t - 2 <= 4: 19 strategies

    /// Strategies (s, t) with s + t - 2 <= kMaxDepth, but for (0, 1) (a light path alone).
    static constexpr int kStrategies = (kMaxDepth + 1) * (kMaxDepth + 4) / 2 - 1;
    /// What the images allocate per pixel: for the camera and the splat part, a weighted and
    /// an unweighted image per strategy, and the weight sums (render_memory.h).
    static constexpr std::size_t bytesPerPixel() {
        return 2 * 2 * kStrategies * sizeof(Rgb<double>) + sizeof(double);
    }

    StrategyImages(int width, int height);

    /// The strategy's slot, or -1 beyond kMaxDepth.
    int slot(int s, int t) const;
    const std::vector<std::pair<int, int>>& strategies() const { return strategies_; }
    /// A camera-side contribution (t >= 2) of a sample with filter weight w.
    void addCamera(int slot, int x, int y, const Rgb<double>& weighted,
                   const Rgb<double>& unweighted, double w) {
        at(0, 2 * slot, x, y) += weighted * w;
        at(0, 2 * slot + 1, x, y) += unweighted * w;
    }
    void addWeight(int x, int y, double w) { weightSums_[std::size_t(y) * width_ + x] += w; }
    /// A splat (t = 1), thread-safe.
    void addSplat(int slot, int x, int y, const Rgb<double>& weighted,
                  const Rgb<double>& unweighted) {
        for (int c = 0; c < 3; ++c) {
            std::atomic_ref<double>(at(1, 2 * slot, x, y)[c]).fetch_add(weighted[c]);
            std::atomic_ref<double>(at(1, 2 * slot + 1, x, y)[c]).fetch_add(unweighted[c]);
        }
    }
    /// A splat (t = 1) at film position `raster`, spread over the pixels the filter covers
    /// (splat.h), thread-safe.
    void splatFiltered(int slot, const PixelFilter& filter, const Vec2<float>& raster,
                       const Rgb<double>& weighted, const Rgb<double>& unweighted);
    /// The image of a strategy (`weighted` or not), in the film's space, after `particles`
    /// light paths in total.
    std::vector<Rgb<double>> image(int slot, bool weighted, double particles) const;
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    Rgb<double>& at(int part, int b, int x, int y) {
        return buffers_[std::size_t(part)][std::size_t(b)][std::size_t(y) * width_ + x];
    }
    int width_, height_;
    std::vector<std::pair<int, int>> strategies_;
    std::array<std::vector<std::vector<Rgb<double>>>, 2> buffers_;  ///< camera, splat
    std::vector<double> weightSums_;
};

}  // namespace lamina::render
