#include "lamina/lights/environment_map.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/math.h"
#include "lamina/lights/equal_area_sphere.h"
#include "lamina/image/image_input.h"

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

namespace {

// The rows of a matrix applied as written: x = r0 . w, ... (summed left to right, so that a
// rotation about +y alone gives the same bits as cos / sin written out).
Vec3<double> apply(const Vec3<double> (&rows)[3], const Vec3<double>& w) {
    Vec3<double> out;
    for (int i = 0; i < 3; ++i)
        out[i] = rows[i].x * w.x + rows[i].y * w.y + rows[i].z * w.z;
    return out;
}

}  // namespace

EnvironmentMap::EnvironmentMap(const std::filesystem::path& file, const EnvironmentLayout& layout) {
    const InputImage image = readInputImage(file, "environment map");
    width_ = image.width;
    height_ = image.height;
    if (layout.mapping == EnvironmentMapping::EqualAreaOctahedral && width_ != height_)
        throw InputError(file.string() +
                         ": an equal_area_octahedral environment map must be square, got " +
                         std::to_string(width_) + " x " + std::to_string(height_) + " pixels");
    if (width_ < 1 || height_ < 1 ||
        (layout.mapping == EnvironmentMapping::Equirectangular && width_ < 2))
        throw InputError(file.string() + ": image too small");
    const int channels = image.channels;
    const std::vector<float>& data = image.samples;
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
    build(layout);
}

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<Rgb<float>> pixels,
                               const EnvironmentLayout& layout)
    : width_(width), height_(height), pixels_(std::move(pixels)) {
    build(layout);
}

void EnvironmentMap::build(const EnvironmentLayout& layout) {
    mapping_ = layout.mapping;
    // T R_y, R_y the right-handed rotation about +y: [c 0 s; 0 1 0; -s 0 c].
    const double c = std::cos(radians(layout.rotateDegrees)),
                 s = std::sin(radians(layout.rotateDegrees));
    const Mat3<double> rotateY(c, 0, -s, 0, 1, 0, s, 0, c);  // glm: column by column
    const Mat3<double> m = layout.orientation * rotateY;
    for (int i = 0; i < 3; ++i) {
        worldFromMap_[i] = Vec3<double>(m[0][i], m[1][i], m[2][i]);
        mapFromWorld_[i] = m[i];  // the transpose: the inverse of an orthogonal matrix
    }
    std::vector<double> marginal(static_cast<std::size_t>(height_));
    double weighted = 0, weights = 0;
    for (int y = 0; y < height_; ++y) {
        // Each pixel's share of solid angle: sin(theta) for a latitude-longitude row, equal
        // for the equal-area map.
        const double area = mapping_ == EnvironmentMapping::Equirectangular
                                ? std::sin(kPi<double> * (y + 0.5) / height_)
                                : 1.0;
        std::vector<double> row(static_cast<std::size_t>(width_));
        for (int x = 0; x < width_; ++x) {
            const double lum = luminance(Rgb<double>(pixels_[std::size_t(y) * width_ + x]));
            row[std::size_t(x)] = lum * area;
            weighted += lum * area;
            weights += area;
        }
        rows_.emplace_back(std::move(row));
        marginal[std::size_t(y)] = rows_.back().integral();
    }
    marginal_ = std::make_unique<PiecewiseConstant1D>(std::move(marginal));
    average_ = weights > 0 ? weighted / weights : 0;
}

Vec2<double> EnvironmentMap::toUv(const Vec3<float>& w) const {
    const Vec3<double> d = apply(mapFromWorld_, Vec3<double>(w));
    if (mapping_ == EnvironmentMapping::EqualAreaOctahedral) {
        const Vec2<double> uv = equalAreaSphereToSquare(safeNormalize(d));
        return {std::min(uv.x, 1.0 - 1e-12), std::min(uv.y, 1.0 - 1e-12)};
    }
    const double u = 0.5 + std::atan2(d.x, d.z) / (2 * kPi<double>);
    const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi<double>;
    return {u - std::floor(u), std::clamp(v, 0.0, 1.0 - 1e-12)};
}

Vec3<float> EnvironmentMap::fromUv(double u, double v) const {
    Vec3<double> d;
    if (mapping_ == EnvironmentMapping::EqualAreaOctahedral) {
        d = equalAreaSquareToSphere({u, v});
    } else {
        const double phi = (u - 0.5) * 2 * kPi<double>, theta = v * kPi<double>;
        d = Vec3<double>(std::sin(theta) * std::sin(phi), std::cos(theta),
                         std::sin(theta) * std::cos(phi));
    }
    return Vec3<float>(apply(worldFromMap_, d));
}

int EnvironmentMap::pixelsAroundTheHorizon() const {
    if (mapping_ == EnvironmentMapping::EqualAreaOctahedral)
        return int(std::lround(2 * std::sqrt(2.0) * width_));
    return width_;
}

double EnvironmentMap::solidAnglePerArea(double v) const {
    if (mapping_ == EnvironmentMapping::EqualAreaOctahedral) return 4 * kPi<double>;
    return 2 * kPi<double> * kPi<double> * std::sin(v * kPi<double>);
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
    const double jacobian = solidAnglePerArea(v);
    pdf = jacobian > 0 ? float(pdfU * pdfV / jacobian) : 0.0f;
    return fromUv(uu, v);
}

float EnvironmentMap::pdf(const Vec3<float>& w) const {
    const Vec2<double> uv = toUv(w);
    const double jacobian = solidAnglePerArea(uv.y);
    if (!(jacobian > 0)) return 0.0f;
    const int row = std::min(int(uv.y * height_), height_ - 1);
    return float(marginal_->pdf(uv.y) * rows_[std::size_t(row)].pdf(uv.x) / jacobian);
}

}  // namespace lamina::render
