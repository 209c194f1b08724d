#include "lamina/render/film.h"

#include <algorithm>
#include <cmath>

#include "lamina/spectral/color_space.h"

namespace lamina::render {

Film::Film(int width, int height, FilmSpace space)
    : width_(width),
      height_(height),
      space_(space),
      pixels_(std::size_t(width) * std::size_t(height)),
      splatIteration_(std::size_t(width) * std::size_t(height), Rgb<double>(0.0)) {}

bool Film::addSample(int x, int y, const Rgb<double>& value, double weight) {
    // XYZ may legitimately have no negative components either: reject both the same way.
    if (!value.isFinite() || value.hasNegative() || !std::isfinite(weight)) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    Pixel& p = at(x, y);
    p.sum += value * weight;
    p.weightSum += weight;
    const double lum = space_ == FilmSpace::Xyz ? value[1] : luminance(value);
    p.ySum += lum * weight;
    p.ySqSum += lum * lum * weight;
    p.yMax = std::max(p.yMax, lum);
    ++p.count;
    return true;
}

double Film::largestSampleLuminance() const {
    double m = 0;
    for (const Pixel& p : pixels_)
        m = std::max(m, p.yMax);
    return m;
}

void Film::addAovs(int x, int y, const PixelAovs& a) {
    Pixel& p = at(x, y);
    p.aovSum.albedo += a.albedo;
    p.aovSum.normal += a.normal;
    p.aovSum.depth += a.depth;
}

bool Film::addSplat(int x, int y, const Rgb<double>& value) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return false;
    if (!value.isFinite() || value.hasNegative()) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    Rgb<double>& target = splatIteration_[std::size_t(y) * width_ + x];
    for (int c = 0; c < 3; ++c)
        std::atomic_ref<double>(target[c]).fetch_add(value[c], std::memory_order_relaxed);
    return true;
}

void Film::endSplatIteration(double scale) {
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
        const Rgb<double> v = splatIteration_[i] * scale;
        splatIteration_[i] = Rgb<double>(0.0);
        const double lum = space_ == FilmSpace::Xyz ? v[1] : luminance(v);
        Pixel& p = pixels_[i];
        p.splatSum += v;
        p.splatYSum += lum;
        p.splatYSqSum += lum * lum;
    }
    ++splatIterations_;
}

Rgb<double> Film::toRec709(const Rgb<double>& v) const {
    if (space_ == FilmSpace::Rec709) return v;
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(Vec3d(v[0], v[1], v[2]));
    return Rgb<double>(rgb.x, rgb.y, rgb.z);
}

Rgb<double> Film::pixel(int x, int y) const {
    const Pixel& p = at(x, y);
    Rgb<double> v = p.weightSum > 0 ? p.sum / p.weightSum : Rgb<double>(0.0);
    if (splatIterations_ > 0) v += p.splatSum / double(splatIterations_);
    return toRec709(v);
}

namespace {
/// Variance of the mean of n samples from their (weighted) sums of values and squares.
double varianceOfMeanFromSums(double sum, double sqSum, double weightSum, double n) {
    if (n < 2 || !(weightSum > 0)) return 0.0;
    const double mean = sum / weightSum;
    const double var = std::max(0.0, sqSum / weightSum - mean * mean);
    return var * n / (n - 1) / n;
}
}  // namespace

double Film::varianceOfMean(int x, int y) const {
    const Pixel& p = at(x, y);
    const double n = double(splatIterations_);
    return varianceOfMeanFromSums(p.ySum, p.ySqSum, p.weightSum, double(p.count)) +
           varianceOfMeanFromSums(p.splatYSum, p.splatYSqSum, n, n);
}

PixelAovs Film::aovs(int x, int y) const {
    const Pixel& p = at(x, y);
    PixelAovs a = p.aovSum;
    if (p.count == 0) return a;
    const double n = double(p.count);
    a.albedo = toRec709(a.albedo / n);
    a.normal = a.normal / n;
    a.depth /= n;
    return a;
}

}  // namespace lamina::render
