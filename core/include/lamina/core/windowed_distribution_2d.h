// A piecewise-constant density on the unit square that is sampled within any axis-aligned
// window of it: the density restricted to the window and renormalised there. A summed-area
// table makes every window's integral four lookups, so a sample costs two binary searches
// whatever the window (the construction pbrt-v4's WindowedPiecewiseConstant2D uses for portal
// lights, after Bitterli, Novak and Jarosz 2015, "Portal-Masked Environment Map Sampling";
// written here from the definitions).
//
// Cell (i, j) of an nx x ny grid covers [i / nx, (i + 1) / nx) x [j / ny, (j + 1) / ny) and
// holds a value f >= 0. The integral of f over [0, u] x [0, v] is bilinear within each cell,
// so it is exactly the bilinear interpolation of the table's corner values, and a window's
// integral follows from four such values even when the window cuts cells.
#pragma once

#include <optional>
#include <vector>

#include "lamina/core/vector.h"

namespace lamina {

/// An axis-aligned window of the unit square, lo <= hi componentwise.
struct UnitWindow {
    Vec2d lo{0.0}, hi{1.0};
};

class WindowedDistribution2D {
  public:
    WindowedDistribution2D() = default;
    /// `values` row after row (ny rows of nx values, row j at v in [j / ny, (j + 1) / ny));
    /// negative and non-finite values count as zero. nx, ny >= 1 and the size are the caller's
    /// to check (std::invalid_argument otherwise).
    WindowedDistribution2D(int nx, int ny, std::vector<double> values);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    /// The integral of f over a window.
    double integral(const UnitWindow& w) const;
    /// A point of the window with density f / integral(window) there; nullopt when the window
    /// holds no mass. `pdf` receives the density (per unit area of the square).
    std::optional<Vec2d> sample(const Vec2d& u, const UnitWindow& w, double& pdf) const;
    /// The density of sample() within window `w` at `p` (0 outside it).
    double pdf(const Vec2d& p, const UnitWindow& w) const;

  private:
    /// The integral of f over [0, u] x [0, v].
    double cumulative(double u, double v) const;
    double cell(int i, int j) const {
        return f_[std::size_t(j) * std::size_t(nx_) + std::size_t(i)];
    }

    int nx_ = 0, ny_ = 0;
    std::vector<double> f_;
    /// (nx + 1) x (ny + 1) corner sums: sat_[j][i] = integral over [0, i/nx] x [0, j/ny].
    std::vector<double> sat_;
};

}  // namespace lamina
