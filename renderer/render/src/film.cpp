#include "lamina/render/film.h"

#include <algorithm>
#include <cmath>

#include "lamina/spectral/color_space.h"

namespace lamina::render {

void PixelSums::add(const PixelSums& o) {
    sum += o.sum;
    weightSum += o.weightSum;
    ySum += o.ySum;
    ySqSum += o.ySqSum;
    yMax = std::max(yMax, o.yMax);
    count += o.count;
    aovSum.albedo += o.aovSum.albedo;
    aovSum.normal += o.aovSum.normal;
    aovSum.depth += o.aovSum.depth;
    splatSum += o.splatSum;
    splatYSum += o.splatYSum;
    splatYSqSum += o.splatYSqSum;
    splatCount += o.splatCount;
    sqSum += o.sqSum;
    splatSqSum += o.splatSqSum;
}

Film::Film(int width, int height, FilmSpace space)
    : Film(width, height, PixelBounds{0, width, 0, height}, space) {}

Film::Film(int fullWidth, int fullHeight, const PixelBounds& window, FilmSpace space)
    : width_(window.width()),
      height_(window.height()),
      fullWidth_(fullWidth),
      fullHeight_(fullHeight),
      window_(window),
      space_(space),
      xyzToRec709_(RgbColorSpace::rec709().xyzToRgb()),
      pixels_(std::size_t(width_) * std::size_t(height_)),
      splatIteration_(std::size_t(width_) * std::size_t(height_), Rgb<double>(0.0)) {}

bool Film::addSample(int x, int y, const Rgb<double>& value, double weight,
                     const SpectralFilmSample* spectral) {
    if (!spectral) return addValue(x, y, value, weight);
    if (!window_.contains(x, y)) return false;
    if (!spectral->isFinite()) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    if (!addValue(x, y, value, weight)) return false;
    spectral_->addSample(windowIndex(x, y), *spectral, weight * response_.scaleAlongside(value));
    return true;
}

bool Film::addValue(int x, int y, const Rgb<double>& value, double weight) {
    if (!window_.contains(x, y)) return false;
    // XYZ may legitimately have no negative components either: reject both the same way.
    if (!value.isFinite() || value.hasNegative() || !std::isfinite(weight)) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    if (response_.isIdentity()) return accumulate(x, y, value, weight);
    // After the check: a white balance may turn a valid saturated colour slightly negative.
    const Rgb<double> v = response_.apply(value);
    if (!v.isFinite()) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    return accumulate(x, y, v, weight);
}

bool Film::polarisationFinite(const std::array<Rgb<double>, 4>& stokes) {
    for (std::size_t i = 1; i < 4; ++i)
        if (!stokes[i].isFinite()) {
            rejected_.fetch_add(1, std::memory_order_relaxed);
            return false;
        }
    return true;
}

bool Film::addPolarisedSample(int x, int y, const std::array<Rgb<double>, 4>& stokes, double weight,
                              const SpectralFilmSample* spectral) {
    if (!window_.contains(x, y) || !polarisationFinite(stokes)) return false;
    if (!addSample(x, y, stokes[0], weight, spectral)) return false;
    StokesSums& sums = stokes_[std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0)];
    for (std::size_t i = 0; i < 3; ++i)
        sums[i] += response_.applyAlongside(stokes[0], stokes[i + 1]) * weight;
    return true;
}

bool Film::addPolarisedSplat(int x, int y, const std::array<Rgb<double>, 4>& stokes, double weight,
                             const SpectralFilmSample* spectral) {
    if (!window_.contains(x, y) || !polarisationFinite(stokes)) return false;
    if (!addSplat(x, y, stokes[0], weight, spectral)) return false;
    StokesSums& target =
        stokesSplatIteration_[std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0)];
    for (std::size_t i = 0; i < 3; ++i) {
        const Rgb<double> v = response_.applyAlongside(stokes[0], stokes[i + 1]) * weight;
        for (int c = 0; c < 3; ++c)
            std::atomic_ref<double>(target[i][c]).fetch_add(v[c], std::memory_order_relaxed);
    }
    return true;
}

std::array<Rgb<double>, 4> Film::stokes(int x, int y) const {
    const Pixel& p = at(x, y);
    const std::size_t i = std::size_t(y) * width_ + std::size_t(x);
    std::array<Rgb<double>, 4> s{pixel(x, y), Rgb<double>(0.0), Rgb<double>(0.0), Rgb<double>(0.0)};
    for (std::size_t k = 0; k < 3; ++k) {
        Rgb<double> v = p.weightSum > 0 ? stokes_[i][k] / p.weightSum : Rgb<double>(0.0);
        if (p.splatCount > 0) v += stokesSplatSum_[i][k] / double(p.splatCount);
        s[k + 1] = toRec709(v);
    }
    return s;
}

void Film::addStokesSums(int x, int y, const StokesSums& camera, const StokesSums& splat) {
    if (!window_.contains(x, y)) return;
    const std::size_t i = std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0);
    for (std::size_t k = 0; k < 3; ++k) {
        stokes_[i][k] += camera[k];
        stokesSplatSum_[i][k] += splat[k];
    }
}

bool Film::accumulate(int x, int y, const Rgb<double>& value, double weight) {
    Pixel& p = at(x - window_.x0, y - window_.y0);
    p.sum += value * weight;
    p.weightSum += weight;
    const double lum = space_ == FilmSpace::Xyz ? value[1] : luminance(value);
    p.ySum += lum * weight;
    p.ySqSum += lum * lum * weight;
    p.yMax = std::max(p.yMax, lum);
    const Rgb<double> rgb = toRec709(value);
    p.sqSum += rgb * rgb * weight;
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
    if (!window_.contains(x, y)) return;
    Pixel& p = at(x - window_.x0, y - window_.y0);
    p.aovSum.albedo += a.albedo;
    p.aovSum.normal += a.normal;
    p.aovSum.depth += a.depth;
}

bool Film::addSplat(int x, int y, const Rgb<double>& value, double weight,
                    const SpectralFilmSample* spectral) {
    if (!window_.contains(x, y)) return false;
    if (!value.isFinite() || value.hasNegative() || (spectral && !spectral->isFinite())) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    const Rgb<double> v = response_.isIdentity() ? value * weight : response_.apply(value) * weight;
    if (!v.isFinite()) {
        rejected_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    Rgb<double>& target =
        splatIteration_[std::size_t(y - window_.y0) * width_ + std::size_t(x - window_.x0)];
    for (int c = 0; c < 3; ++c)
        std::atomic_ref<double>(target[c]).fetch_add(v[c], std::memory_order_relaxed);
    if (spectral)
        spectral_->addSplat(windowIndex(x, y), *spectral, weight * response_.scaleAlongside(value));
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
        const Rgb<double> rgb = toRec709(v);
        p.splatSqSum += rgb * rgb;
        ++p.splatCount;
        if (hasStokes())
            for (std::size_t k = 0; k < 3; ++k) {
                stokesSplatSum_[i][k] += stokesSplatIteration_[i][k] * scale;
                stokesSplatIteration_[i][k] = Rgb<double>(0.0);
            }
    }
    if (spectral_ && spectral_->splats()) spectral_->endSplatIteration(scale);
    ++splatIterations_;
}

Rgb<double> Film::toRec709(const Rgb<double>& v) const {
    if (space_ == FilmSpace::Rec709) return v;
    const Vec3d rgb = xyzToRec709_ * Vec3d(v[0], v[1], v[2]);
    return Rgb<double>(rgb.x, rgb.y, rgb.z);
}

Rgb<double> Film::pixel(int x, int y) const {
    const Pixel& p = at(x, y);
    Rgb<double> v = p.weightSum > 0 ? p.sum / p.weightSum : Rgb<double>(0.0);
    if (p.splatCount > 0) v += p.splatSum / double(p.splatCount);
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
    const double n = double(p.splatCount);
    return varianceOfMeanFromSums(p.ySum, p.ySqSum, p.weightSum, double(p.count)) +
           varianceOfMeanFromSums(p.splatYSum, p.splatYSqSum, n, n);
}

Rgb<double> Film::varianceOfMeanRgb(int x, int y) const {
    const Pixel& p = at(x, y);
    const double n = double(p.splatCount);
    const Rgb<double> sum = toRec709(p.sum), splat = toRec709(p.splatSum);
    Rgb<double> v(0.0);
    for (int c = 0; c < 3; ++c)
        v[c] = varianceOfMeanFromSums(sum[c], p.sqSum[c], p.weightSum, double(p.count)) +
               varianceOfMeanFromSums(splat[c], p.splatSqSum[c], n, n);
    return v;
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
