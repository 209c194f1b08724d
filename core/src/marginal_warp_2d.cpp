#include "lamina/core/marginal_warp_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lamina {

namespace {

// The largest i in [0, size - 2] with below(i) true (0 when there is none); below must be true
// up to some index and false after it.
template <typename Below>
std::size_t findInterval(std::size_t size, const Below& below) {
    std::size_t lo = 0, hi = size - 1;  // below(lo) is assumed, hi is past the answer
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        if (below(mid))
            lo = mid;
        else
            hi = mid;
    }
    return std::min(lo, size - 2);
}

// The root t in [0, 1] of a t + (b - a) t^2 / 2 = s: where the integral of the linear function
// from a (at 0) to b (at 1) reaches s.
double invertLinearIntegral(double a, double b, double s) {
    if (std::abs(a - b) <= 1e-4 * (a + b)) {
        const double sum = a + b;
        return sum > 0 ? std::clamp(2 * s / sum, 0.0, 1.0) : 0.0;
    }
    const double t = (a - std::sqrt(std::max(0.0, a * a + 2 * s * (b - a)))) / (a - b);
    return std::clamp(t, 0.0, 1.0);
}

}  // namespace

MarginalWarp2D::MarginalWarp2D(int nx, int ny, std::vector<std::vector<float>> parameters,
                               std::vector<float> values, Kind kind)
    : nx_(nx),
      ny_(ny),
      kind_(kind),
      parameters_(std::move(parameters)),
      values_(std::move(values)) {
    if (nx < 2 || ny < 2 || parameters_.size() > kMaxParameters)
        throw std::invalid_argument("MarginalWarp2D: a grid of at least 2 x 2, 3 parameters");
    std::size_t slices = 1;
    for (const auto& grid : parameters_) {
        if (grid.empty()) throw std::invalid_argument("MarginalWarp2D: an empty parameter grid");
        for (std::size_t i = 1; i < grid.size(); ++i)
            if (!(grid[i] > grid[i - 1]))
                throw std::invalid_argument("MarginalWarp2D: a parameter grid must increase");
        slices *= grid.size();
    }
    if (values_.size() != slices * std::size_t(nx) * std::size_t(ny))
        throw std::invalid_argument("MarginalWarp2D: values do not fill the slices");
    if (kind_ == Kind::Density) buildCdfs();
}

void MarginalWarp2D::buildCdfs() {
    const std::size_t nx = std::size_t(nx_), ny = std::size_t(ny_), perSlice = nx * ny;
    const std::size_t slices = values_.size() / perSlice;
    conditionalCdf_.assign(values_.size(), 0.0f);
    marginalCdf_.assign(slices * ny, 0.0f);
    for (std::size_t s = 0; s < slices; ++s) {
        float* v = values_.data() + s * perSlice;
        for (std::size_t i = 0; i < perSlice; ++i)
            v[i] = std::isfinite(v[i]) ? std::max(v[i], 0.0f) : 0.0f;
        // Trapezoids in units of the grid spacing: exact integrals of the bilinear interpolant.
        auto integrate = [&](std::vector<double>& cond, std::vector<double>& marg) {
            for (std::size_t y = 0; y < ny; ++y) {
                double sum = 0;
                cond[y * nx] = 0;
                for (std::size_t x = 0; x + 1 < nx; ++x) {
                    sum += 0.5 * (double(v[y * nx + x]) + double(v[y * nx + x + 1]));
                    cond[y * nx + x + 1] = sum;
                }
            }
            marg[0] = 0;
            for (std::size_t y = 0; y + 1 < ny; ++y)
                marg[y + 1] = marg[y] + 0.5 * (cond[y * nx + nx - 1] + cond[(y + 1) * nx + nx - 1]);
            return marg[ny - 1];
        };
        std::vector<double> cond(perSlice), marg(ny);
        double total = integrate(cond, marg);
        if (!(total > 0) || !std::isfinite(total)) {  // no mass: sample the square uniformly
            std::fill(v, v + perSlice, 1.0f);
            total = integrate(cond, marg);
        }
        const double scale = 1.0 / total;
        for (std::size_t i = 0; i < perSlice; ++i) {
            v[i] = float(double(v[i]) * scale);
            conditionalCdf_[s * perSlice + i] = float(cond[i] * scale);
        }
        for (std::size_t y = 0; y < ny; ++y)
            marginalCdf_[s * ny + y] = float(marg[y] * scale);
    }
}

MarginalWarp2D::Corners MarginalWarp2D::corners(std::span<const double> parameters) const {
    Corners c;
    c.count = 1;
    c.weight[0] = 1;
    c.slice[0] = 0;
    for (std::size_t d = 0; d < parameters_.size(); ++d) {
        const auto& grid = parameters_[d];
        const double x = d < parameters.size() ? parameters[d] : 0.0;
        for (int k = 0; k < c.count; ++k)
            c.slice[std::size_t(k)] *= grid.size();
        if (grid.size() == 1) continue;
        const std::size_t i =
            findInterval(grid.size(), [&](std::size_t k) { return double(grid[k]) < x; });
        const double w1 =
            std::clamp((x - double(grid[i])) / (double(grid[i + 1]) - double(grid[i])), 0.0, 1.0);
        const int n = c.count;
        for (int k = 0; k < n; ++k) {
            const std::size_t base = c.slice[std::size_t(k)] + i;
            const double w = c.weight[std::size_t(k)];
            c.slice[std::size_t(k)] = base;
            c.weight[std::size_t(k)] = w * (1 - w1);
            c.slice[std::size_t(n + k)] = base + 1;
            c.weight[std::size_t(n + k)] = w * w1;
        }
        c.count = 2 * n;
    }
    return c;
}

double MarginalWarp2D::lookup(const std::vector<float>& array, std::size_t perSlice,
                              std::size_t index, const Corners& c) {
    double sum = 0;
    for (int k = 0; k < c.count; ++k)
        sum += c.weight[std::size_t(k)] * double(array[c.slice[std::size_t(k)] * perSlice + index]);
    return sum;
}

double MarginalWarp2D::value(std::size_t index, const Corners& c) const {
    return lookup(values_, std::size_t(nx_) * std::size_t(ny_), index, c);
}

double MarginalWarp2D::conditional(std::size_t index, const Corners& c) const {
    return lookup(conditionalCdf_, std::size_t(nx_) * std::size_t(ny_), index, c);
}

double MarginalWarp2D::marginal(std::size_t row, const Corners& c) const {
    return lookup(marginalCdf_, std::size_t(ny_), row, c);
}

double MarginalWarp2D::eval(const Vec2d& p, std::span<const double> parameters) const {
    const Corners c = corners(parameters);
    const double qx = std::clamp(p.x, 0.0, 1.0) * (nx_ - 1),
                 qy = std::clamp(p.y, 0.0, 1.0) * (ny_ - 1);
    const int col = std::min(int(qx), nx_ - 2), row = std::min(int(qy), ny_ - 2);
    const double s = qx - col, t = qy - row;
    const std::size_t i = std::size_t(row) * std::size_t(nx_) + std::size_t(col);
    const std::size_t nx = std::size_t(nx_);
    const double v = (1 - t) * ((1 - s) * value(i, c) + s * value(i + 1, c)) +
                     t * ((1 - s) * value(i + nx, c) + s * value(i + nx + 1, c));
    return kind_ == Kind::Density ? v * double(nx_ - 1) * double(ny_ - 1) : v;
}

std::pair<Vec2d, double> MarginalWarp2D::sample(const Vec2d& u,
                                                std::span<const double> parameters) const {
    const Corners c = corners(parameters);
    const std::size_t nx = std::size_t(nx_), ny = std::size_t(ny_);
    const double uy = std::clamp(u.y, 0.0, 1.0), ux = std::clamp(u.x, 0.0, 1.0);
    // The row: the marginal density is linear in y within a row, from r0 to r1.
    const std::size_t row = findInterval(ny, [&](std::size_t j) { return marginal(j, c) < uy; });
    const double r0 = conditional(row * nx + nx - 1, c),
                 r1 = conditional((row + 1) * nx + nx - 1, c);
    const double t = invertLinearIntegral(r0, r1, uy - marginal(row, c));
    // The column, in the row interpolated at t.
    const double target = ux * ((1 - t) * r0 + t * r1);
    auto rowCdf = [&](std::size_t x) {
        return (1 - t) * conditional(row * nx + x, c) + t * conditional((row + 1) * nx + x, c);
    };
    const std::size_t col = findInterval(nx, [&](std::size_t x) { return rowCdf(x) < target; });
    const std::size_t i = row * nx + col;
    const double c0 = (1 - t) * value(i, c) + t * value(i + nx, c),
                 c1 = (1 - t) * value(i + 1, c) + t * value(i + nx + 1, c);
    const double s = invertLinearIntegral(c0, c1, target - rowCdf(col));
    const Vec2d p((double(col) + s) / double(nx_ - 1), (double(row) + t) / double(ny_ - 1));
    return {p, ((1 - s) * c0 + s * c1) * double(nx_ - 1) * double(ny_ - 1)};
}

std::pair<Vec2d, double> MarginalWarp2D::invert(const Vec2d& p,
                                                std::span<const double> parameters) const {
    const Corners c = corners(parameters);
    const std::size_t nx = std::size_t(nx_);
    const double qx = std::clamp(p.x, 0.0, 1.0) * (nx_ - 1),
                 qy = std::clamp(p.y, 0.0, 1.0) * (ny_ - 1);
    const int colI = std::min(int(qx), nx_ - 2), rowI = std::min(int(qy), ny_ - 2);
    const std::size_t col = std::size_t(colI), row = std::size_t(rowI);
    const double s = qx - colI, t = qy - rowI;
    const std::size_t i = row * nx + col;
    const double c0 = (1 - t) * value(i, c) + t * value(i + nx, c),
                 c1 = (1 - t) * value(i + 1, c) + t * value(i + nx + 1, c);
    const double r0 = conditional(row * nx + nx - 1, c),
                 r1 = conditional((row + 1) * nx + nx - 1, c);
    const double rowTotal = (1 - t) * r0 + t * r1;
    const double x =
        s * (c0 + 0.5 * s * (c1 - c0)) + (1 - t) * conditional(i, c) + t * conditional(i + nx, c);
    const double y = t * (r0 + 0.5 * t * (r1 - r0)) + marginal(row, c);
    const Vec2d u(rowTotal > 0 ? std::clamp(x / rowTotal, 0.0, 1.0) : 0.0, std::clamp(y, 0.0, 1.0));
    return {u, ((1 - s) * c0 + s * c1) * double(nx_ - 1) * double(ny_ - 1)};
}

}  // namespace lamina
