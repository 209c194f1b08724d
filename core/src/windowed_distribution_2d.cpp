#include "lamina/core/windowed_distribution_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lamina {

namespace {

/// The cell of coordinate x in [0, 1] on a grid of n cells, and the fraction of it below x.
std::pair<int, double> cellOf(double x, int n) {
    const double s = std::clamp(x, 0.0, 1.0) * n;
    const int i = std::min(int(s), n - 1);
    return {i, s - i};
}

/// The largest k in [lo, hi - 1] with below(k) <= target (below increasing in k).
template <typename F>
int lastAtMost(int lo, int hi, double target, const F& below) {
    int a = lo, b = hi - 1;
    while (a < b) {
        const int mid = (a + b + 1) / 2;
        if (below(mid) <= target)
            a = mid;
        else
            b = mid - 1;
    }
    return a;
}

/// The point of [xA, xB] where a function linear there from fA to fB reaches target.
double invertLinear(double xA, double xB, double fA, double fB, double target) {
    if (!(fB > fA)) return xA;
    return std::clamp(xA + (target - fA) / (fB - fA) * (xB - xA), xA, xB);
}

}  // namespace

WindowedDistribution2D::WindowedDistribution2D(int nx, int ny, std::vector<double> values)
    : nx_(nx), ny_(ny), f_(std::move(values)) {
    if (nx < 1 || ny < 1 || f_.size() != std::size_t(nx) * std::size_t(ny))
        throw std::invalid_argument("WindowedDistribution2D: the grid's size");
    for (double& v : f_)
        if (!(v > 0.0) || !std::isfinite(v)) v = 0.0;
    const double cellArea = 1.0 / (double(nx) * double(ny));
    const std::size_t w = std::size_t(nx) + 1;
    sat_.assign(w * (std::size_t(ny) + 1), 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            sat_[(std::size_t(j) + 1) * w + std::size_t(i) + 1] =
                cell(i, j) * cellArea + sat_[std::size_t(j) * w + std::size_t(i) + 1] +
                sat_[(std::size_t(j) + 1) * w + std::size_t(i)] -
                sat_[std::size_t(j) * w + std::size_t(i)];
}

double WindowedDistribution2D::cumulative(double u, double v) const {
    const auto [i, fx] = cellOf(u, nx_);
    const auto [j, fy] = cellOf(v, ny_);
    const std::size_t w = std::size_t(nx_) + 1;
    const auto at = [&](int x, int y) { return sat_[std::size_t(y) * w + std::size_t(x)]; };
    return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
           fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
}

double WindowedDistribution2D::integral(const UnitWindow& w) const {
    return std::max(cumulative(w.hi.x, w.hi.y) - cumulative(w.lo.x, w.hi.y) -
                        cumulative(w.hi.x, w.lo.y) + cumulative(w.lo.x, w.lo.y),
                    0.0);
}

std::optional<Vec2d> WindowedDistribution2D::sample(const Vec2d& u, const UnitWindow& w,
                                                    double& pdf) const {
    pdf = 0.0;
    const double total = integral(w);
    if (!(total > 0.0) || nx_ == 0) return std::nullopt;

    // The row: invert the window's marginal, linear between row boundaries. At a row boundary
    // m inside the window the mass below is two interpolations along row m of the table (the
    // window's sides cut the same two columns on every row), where the general case reads four
    // rows: the binary search touches a quarter of the memory, which is what a sample costs.
    const std::size_t stride = std::size_t(nx_) + 1;
    // (Not structured bindings: clang 14 cannot capture them in the lambda.)
    const std::pair<int, double> lo = cellOf(w.lo.x, nx_), hi = cellOf(w.hi.x, nx_);
    const std::size_t loI = std::size_t(lo.first), hiI = std::size_t(hi.first);
    const double loFx = lo.second, hiFx = hi.second;
    const double below = cumulative(w.hi.x, w.lo.y) - cumulative(w.lo.x, w.lo.y);
    const auto massBelowRow = [&](int m) {
        const double v = double(m) / ny_;
        if (v <= w.lo.y) return 0.0;
        if (v >= w.hi.y) return total;
        const double* row = &sat_[std::size_t(m) * stride];
        return (1 - hiFx) * row[hiI] + hiFx * row[hiI + 1] - (1 - loFx) * row[loI] -
               loFx * row[loI + 1] - below;
    };
    const int rowLo = cellOf(w.lo.y, ny_).first, rowHi = int(std::ceil(w.hi.y * ny_));
    const auto rowEdge = [&](int k) { return std::clamp(double(k) / ny_, w.lo.y, w.hi.y); };
    const double targetV = u.y * total;
    const int k = lastAtMost(rowLo, std::max(rowHi, rowLo + 1), targetV, massBelowRow);
    const double v =
        invertLinear(rowEdge(k), rowEdge(k + 1), massBelowRow(k), massBelowRow(k + 1), targetV);
    const int j = std::clamp(k, 0, ny_ - 1);

    // The column within row j: its prefix sums are the difference of two rows of the table.
    const auto rowPrefix = [&](double x) {
        const auto [i, fx] = cellOf(x, nx_);
        const auto d = [&](int c) {
            return sat_[(std::size_t(j) + 1) * stride + std::size_t(c)] -
                   sat_[std::size_t(j) * stride + std::size_t(c)];
        };
        return (1 - fx) * d(i) + fx * d(i + 1);
    };
    const double start = rowPrefix(w.lo.x), rowMass = rowPrefix(w.hi.x) - start;
    if (!(rowMass > 0.0)) return std::nullopt;
    const double targetU = start + u.x * rowMass;
    const int colLo = cellOf(w.lo.x, nx_).first, colHi = int(std::ceil(w.hi.x * nx_));
    const auto colEdge = [&](int c) { return std::clamp(double(c) / nx_, w.lo.x, w.hi.x); };
    const int c = lastAtMost(colLo, std::max(colHi, colLo + 1), targetU,
                             [&](int m) { return rowPrefix(colEdge(m)); });
    const double x = invertLinear(colEdge(c), colEdge(c + 1), rowPrefix(colEdge(c)),
                                  rowPrefix(colEdge(c + 1)), targetU);

    const Vec2d p(x, v);
    pdf = cell(cellOf(x, nx_).first, cellOf(v, ny_).first) / total;
    if (!(pdf > 0.0)) return std::nullopt;
    return p;
}

double WindowedDistribution2D::pdf(const Vec2d& p, const UnitWindow& w) const {
    if (nx_ == 0 || p.x < w.lo.x || p.x > w.hi.x || p.y < w.lo.y || p.y > w.hi.y) return 0.0;
    const double total = integral(w);
    if (!(total > 0.0)) return 0.0;
    return cell(cellOf(p.x, nx_).first, cellOf(p.y, ny_).first) / total;
}

}  // namespace lamina
