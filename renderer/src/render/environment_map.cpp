#include "lamina/render/environment_map.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/math.h"
#include "lamina/render/stderr_capture.h"

namespace lamina::render {

PiecewiseConstant1D::PiecewiseConstant1D(std::vector<double> f) : f_(std::move(f)) {
    const std::size_t n = f_.size();
    cdf_.resize(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        cdf_[i + 1] = cdf_[i] + std::max(f_[i], 0.0) / double(n);
    integral_ = cdf_[n];
    if (integral_ > 0) {
        for (double& c : cdf_)
            c /= integral_;
    } else {  // all zero: uniform
        for (std::size_t i = 0; i <= n; ++i)
            cdf_[i] = double(i) / double(n);
    }
}

double PiecewiseConstant1D::sample(double u, double& pdf, int& cell) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    cell = std::clamp(int(it - cdf_.begin()) - 1, 0, size() - 1);
    const double c0 = cdf_[std::size_t(cell)], c1 = cdf_[std::size_t(cell) + 1];
    const double t = c1 > c0 ? (u - c0) / (c1 - c0) : 0.5;
    pdf = integral_ > 0 ? std::max(f_[std::size_t(cell)], 0.0) / integral_ : 1.0;
    return std::min((cell + t) / size(), 1.0 - 1e-12);
}

double PiecewiseConstant1D::pdf(double x) const {
    const int i = std::clamp(int(x * size()), 0, size() - 1);
    return integral_ > 0 ? std::max(f_[std::size_t(i)], 0.0) / integral_ : 1.0;
}

EnvironmentMap::EnvironmentMap(const std::filesystem::path& file, double rotationDegrees) {
    const StderrCapture quiet;  // libpng writes its warnings to stderr
    auto in = OIIO::ImageInput::open(file.string());
    if (!in)
        throw InputError(file.string() + ": cannot read the environment map: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    width_ = spec.width;
    height_ = spec.height;
    if (width_ < 2 || height_ < 1) throw InputError(file.string() + ": image too small");
    const int channels = std::min(spec.nchannels, 3);
    std::vector<float> data(std::size_t(width_) * height_ * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
        throw InputError(file.string() + ": cannot read the environment map: " + in->geterror());
    pixels_.resize(std::size_t(width_) * height_);
    for (std::size_t i = 0; i < pixels_.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v =
                data[i * std::size_t(channels) + std::size_t(std::min(c, channels - 1))];
            if (!std::isfinite(v) || v < 0)
                throw InputError(file.string() + ": pixel " + std::to_string(i) +
                                 " is negative or not finite");
            pixels_[i][c] = v;
        }
    build(rotationDegrees);
}

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<Rgb<float>> pixels,
                               double rotationDegrees)
    : width_(width), height_(height), pixels_(std::move(pixels)) {
    build(rotationDegrees);
}

void EnvironmentMap::build(double rotationDegrees) {
    cosRot_ = std::cos(radians(rotationDegrees));
    sinRot_ = std::sin(radians(rotationDegrees));
    std::vector<double> marginal(static_cast<std::size_t>(height_));
    double weighted = 0, weights = 0;
    for (int y = 0; y < height_; ++y) {
        const double sinTheta = std::sin(kPi<double> * (y + 0.5) / height_);
        std::vector<double> row(static_cast<std::size_t>(width_));
        for (int x = 0; x < width_; ++x) {
            const double lum = luminance(Rgb<double>(pixels_[std::size_t(y) * width_ + x]));
            row[std::size_t(x)] = lum * sinTheta;
            weighted += lum * sinTheta;
            weights += sinTheta;
        }
        rows_.emplace_back(std::move(row));
        marginal[std::size_t(y)] = rows_.back().integral();
    }
    marginal_ = std::make_unique<PiecewiseConstant1D>(std::move(marginal));
    average_ = weights > 0 ? weighted / weights : 0;
}

Vec2<double> EnvironmentMap::toUv(const Vec3<float>& w) const {
    // Undo the map's rotation about +y.
    const double x = cosRot_ * w.x - sinRot_ * w.z, z = sinRot_ * w.x + cosRot_ * w.z;
    const double u = 0.5 + std::atan2(x, z) / (2 * kPi<double>);
    const double v = std::acos(std::clamp(double(w.y), -1.0, 1.0)) / kPi<double>;
    return {u - std::floor(u), std::clamp(v, 0.0, 1.0 - 1e-12)};
}

Vec3<float> EnvironmentMap::fromUv(double u, double v) const {
    const double phi = (u - 0.5) * 2 * kPi<double>, theta = v * kPi<double>;
    const double x = std::sin(theta) * std::sin(phi), z = std::sin(theta) * std::cos(phi);
    return Vec3<float>(float(cosRot_ * x + sinRot_ * z), float(std::cos(theta)),
                       float(-sinRot_ * x + cosRot_ * z));
}

Rgb<float> EnvironmentMap::lookup(const Vec3<float>& w) const {
    const Vec2<double> uv = toUv(w);
    const int x = std::min(int(uv.x * width_), width_ - 1),
              y = std::min(int(uv.y * height_), height_ - 1);
    return pixels_[std::size_t(y) * width_ + x];
}

Vec3<float> EnvironmentMap::sample(const Vec2<float>& u, float& pdf) const {
    double pdfV, pdfU;
    int row, cell;
    const double v = marginal_->sample(double(u.y), pdfV, row);
    const double uu = rows_[std::size_t(row)].sample(double(u.x), pdfU, cell);
    const double sinTheta = std::sin(v * kPi<double>);
    pdf = sinTheta > 0 ? float(pdfU * pdfV / (2 * kPi<double> * kPi<double> * sinTheta)) : 0.0f;
    return fromUv(uu, v);
}

float EnvironmentMap::pdf(const Vec3<float>& w) const {
    const Vec2<double> uv = toUv(w);
    const double sinTheta = std::sin(uv.y * kPi<double>);
    if (!(sinTheta > 0)) return 0.0f;
    const int row = std::min(int(uv.y * height_), height_ - 1);
    return float(marginal_->pdf(uv.y) * rows_[std::size_t(row)].pdf(uv.x) /
                 (2 * kPi<double> * kPi<double> * sinTheta));
}

}  // namespace lamina::render
