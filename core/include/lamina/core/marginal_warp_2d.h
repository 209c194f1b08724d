// A density on the unit square tabulated at the nodes of a regular grid and interpolated
// bilinearly, sampled by inverting its marginal CDF over rows and then its conditional CDF
// within the row (the continuous marginal-conditional warp of Dupuy and Jakob 2018, "An
// Adaptive Parameterization for Efficient Material Acquisition and Rendering", section 5, which
// the RGL material files store their warps for). The table may depend on up to three further
// parameters, tabulated on grids of their own; between their values the slices are interpolated
// linearly (the CDFs too, which keeps sample and invert exact inverses of each other).
//
// The grid has nx x ny nodes; node (i, j) sits at (i / (nx - 1), j / (ny - 1)). Values are
// stored slice after slice, the first parameter slowest, each slice ny rows of nx values.
// Outside a parameter's grid the nearest slice is used.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "lamina/core/vector.h"

namespace lamina {

class MarginalWarp2D {
  public:
    static constexpr int kMaxParameters = 3;

    /// Whether the table is a density (normalised per slice, with CDFs to sample it) or plain
    /// values (only eval, which then returns the interpolated values as they are).
    enum class Kind { Density, Values };

    MarginalWarp2D() = default;
    /// `nx`, `ny` >= 2; each parameter grid strictly increasing with at least one value;
    /// `values` holds every slice (the product of the grids' sizes, times nx ny). A density's
    /// negative values count as zero, and a slice without any mass becomes uniform. The sizes
    /// are the caller's to check (std::invalid_argument otherwise).
    MarginalWarp2D(int nx, int ny, std::vector<std::vector<float>> parameters,
                   std::vector<float> values, Kind kind);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    std::size_t parameterCount() const { return parameters_.size(); }

    /// The interpolated value at `p` (Values) or the density at `p` (Density).
    double eval(const Vec2d& p, std::span<const double> parameters) const;
    /// Density only: the point of the density that `u` (uniform on the square) maps to, and
    /// its density.
    std::pair<Vec2d, double> sample(const Vec2d& u, std::span<const double> parameters) const;
    /// Density only: the inverse of sample: the uniform point that maps to `p`, and the density
    /// at `p`.
    std::pair<Vec2d, double> invert(const Vec2d& p, std::span<const double> parameters) const;

  private:
    // The slices a parameter point interpolates between: up to 2^3 (slice, weight) pairs.
    struct Corners {
        std::array<std::size_t, 8> slice{};
        std::array<double, 8> weight{};
        int count = 0;
    };
    Corners corners(std::span<const double> parameters) const;
    // An array of `perSlice` values per slice, interpolated between the corners at `index`.
    static double lookup(const std::vector<float>& array, std::size_t perSlice, std::size_t index,
                         const Corners& c);
    double value(std::size_t index, const Corners& c) const;
    double conditional(std::size_t index, const Corners& c) const;
    double marginal(std::size_t row, const Corners& c) const;
    void buildCdfs();

    int nx_ = 0, ny_ = 0;
    Kind kind_ = Kind::Values;
    std::vector<std::vector<float>> parameters_;
    std::vector<float> values_;
    std::vector<float> conditionalCdf_;  ///< per row, in units of the grid spacing
    std::vector<float> marginalCdf_;     ///< per slice, normalised to 1
};

}  // namespace lamina
