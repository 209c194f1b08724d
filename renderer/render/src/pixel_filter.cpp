#include "lamina/render/pixel_filter.h"

#include <algorithm>
#include <cmath>

namespace lamina::render {

namespace {
constexpr int kBins = 512;
constexpr int kGuide = 512;
}  // namespace

PixelFilter::PixelFilter(const FilmDesc& film)
    : kind_(film.filter), radius_(float(film.filterRadius)) {
    if (kind_ == FilterKind::Box) return;
    if (kind_ == FilterKind::Triangle) {
        integral_ = radius_ * radius_;
        return;
    }
    if (kind_ == FilterKind::Gaussian) {
        sigma_ = film.filterSigma ? float(*film.filterSigma) : radius_ / 3.0f;
        gaussianFloor_ = std::exp(-radius_ * radius_ / (2 * sigma_ * sigma_));
    }
    func_.resize(kBins);
    cdf_.resize(kBins + 1);
    cdf_[0] = 0;
    const float dx = 2.0f * radius_ / float(kBins);
    for (int i = 0; i < kBins; ++i) {
        // The bin's mean value by a few midpoints: the tabulated pdf must be close to f so
        // the weights f / pdf stay near constant.
        float sum = 0;
        for (int k = 0; k < 8; ++k)
            sum += evaluate1D(-radius_ + (float(i) + (float(k) + 0.5f) / 8.0f) * dx);
        func_[std::size_t(i)] = std::max(sum / 8.0f, 0.0f);
        cdf_[std::size_t(i) + 1] = cdf_[std::size_t(i)] + func_[std::size_t(i)] * dx;
    }
    integral_ = cdf_.back();
    for (float& c : cdf_)
        c /= integral_;
    guide_.resize(kGuide);
    for (int j = 0, i = 0; j < kGuide; ++j) {
        const float u = float(j) / float(kGuide);
        while (i + 1 < kBins && cdf_[std::size_t(i) + 1] <= u)
            ++i;
        guide_[std::size_t(j)] = i;
    }
}

float PixelFilter::evaluate1D(float x) const {
    if (std::abs(x) > radius_) return 0.0f;
    switch (kind_) {
        case FilterKind::Box:
            return 1.0f;
        case FilterKind::Gaussian:
            return std::max(0.0f, std::exp(-x * x / (2 * sigma_ * sigma_)) - gaussianFloor_);
        case FilterKind::Triangle:
            return radius_ - std::abs(x);
        case FilterKind::BlackmanHarris: {
            const float t = 2.0f * kPi<float> * (x + radius_) / (2.0f * radius_);
            return 0.35875f - 0.48829f * std::cos(t) + 0.14128f * std::cos(2 * t) -
                   0.01168f * std::cos(3 * t);
        }
    }
    return 0.0f;
}

float PixelFilter::normalizedWeight(const Vec2<float>& offset) const {
    const float integral = kind_ == FilterKind::Box ? 2.0f * radius_ : integral_;
    return evaluate1D(offset.x) * evaluate1D(offset.y) / (integral * integral);
}

float PixelFilter::sample1D(float u, float& pdf) const {
    // The last bin i with cdf_[i] <= u (what upper_bound over the cdf gives, minus one),
    // searched upwards from the guide's bin.
    int i = guide_[std::size_t(std::clamp(int(u * float(kGuide)), 0, kGuide - 1))];
    while (i + 1 < kBins && cdf_[std::size_t(i) + 1] <= u)
        ++i;
    const float c0 = cdf_[std::size_t(i)], c1 = cdf_[std::size_t(i) + 1];
    const float t = c1 > c0 ? (u - c0) / (c1 - c0) : 0.5f;
    const float dx = 2.0f * radius_ / float(kBins);
    pdf = func_[std::size_t(i)] / integral_;
    return -radius_ + (float(i) + t) * dx;
}

// The triangle's density (r - |x|) / r^2 has the CDF 1/2 (1 + x/r)^2 on [-r, 0] and
// 1 - 1/2 (1 - x/r)^2 on [0, r]; inverted piece by piece.
float PixelFilter::sampleTriangle(float u) const {
    return u < 0.5f ? radius_ * (std::sqrt(2 * u) - 1) : radius_ * (1 - std::sqrt(2 * (1 - u)));
}

PixelFilter::Sample PixelFilter::sample(const Vec2<float>& u) const {
    if (kind_ == FilterKind::Box)
        return {Vec2<float>((2 * u.x - 1) * radius_, (2 * u.y - 1) * radius_), 1.0f};
    if (kind_ == FilterKind::Triangle) return {{sampleTriangle(u.x), sampleTriangle(u.y)}, 1.0f};
    float px, py;
    const float x = sample1D(u.x, px), y = sample1D(u.y, py);
    // Normalised so that a constant image stays constant: f / pdf / (integral of f)^2 = 1
    // wherever the table matches f.
    const float weight =
        px > 0 && py > 0 ? evaluate1D(x) * evaluate1D(y) / (px * py * integral_ * integral_) : 0.0f;
    return {Vec2<float>(x, y), weight};
}

}  // namespace lamina::render
