#include "lamina/render/film.h"

#include <cmath>

#include "lamina/spectral/color_space.h"

namespace lamina::render {

Film::Film(int width, int height, FilmSpace space)
    : width_(width),
      height_(height),
      space_(space),
      pixels_(std::size_t(width) * std::size_t(height)),
      splats_(std::size_t(width) * std::size_t(height), Rgb<double>(0.0)) {}

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
    ++p.count;
    return true;
}

void Film::addAovs(int x, int y, const PixelAovs& a) {
    Pixel& p = at(x, y);
    p.aovSum.albedo += a.albedo;
    p.aovSum.normal += a.normal;
    p.aovSum.depth += a.depth;
}

void Film::addSplat(float x, float y, const Rgb<double>& value) {
    const int px = int(std::floor(x)), py = int(std::floor(y));
    if (px < 0 || py < 0 || px >= width_ || py >= height_) return;
    if (!value.isFinite() || value.hasNegative()) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    const std::lock_guard<std::mutex> lock(splatMutex_);
    splats_[std::size_t(py) * width_ + px] += value;
}

Rgb<double> Film::toRec709(const Rgb<double>& v) const {
    if (space_ == FilmSpace::Rec709) return v;
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(Vec3d(v[0], v[1], v[2]));
    return Rgb<double>(rgb.x, rgb.y, rgb.z);
}

Rgb<double> Film::pixel(int x, int y, double splatScale) const {
    const Pixel& p = at(x, y);
    Rgb<double> v = p.weightSum > 0 ? p.sum / p.weightSum : Rgb<double>(0.0);
    v += splats_[std::size_t(y) * width_ + x] * splatScale;
    return toRec709(v);
}

double Film::varianceOfMean(int x, int y) const {
    const Pixel& p = at(x, y);
    if (p.count < 2 || !(p.weightSum > 0)) return 0.0;
    const double mean = p.ySum / p.weightSum;
    const double var = std::max(0.0, p.ySqSum / p.weightSum - mean * mean);
    return var * double(p.count) / double(p.count - 1) / double(p.count);
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
