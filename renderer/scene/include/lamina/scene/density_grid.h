// A heterogeneous medium's density (docs/media.md, "Grid media"): a grid of values stretched
// over an axis-aligned box, and the coarse grid of its maxima that delta and ratio tracking
// sample against (the majorants).
#pragma once

#include <cstdint>
#include <vector>

#include "lamina/core/vector.h"

namespace lamina::render {

/// nx x ny x nz densities (>= 0, finite) at the centres of the cells of the unit cube, x
/// fastest, then y, then z. Between centres a density is interpolated trilinearly; beyond the
/// outermost centres it is clamped to the nearest one (Mitsuba 3's gridvolume with its default
/// "clamp" wrap), so a grid of one constant is that constant everywhere in the box.
struct DensityGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<float> values;

    float at(int x, int y, int z) const {
        return values[(std::size_t(z) * std::size_t(ny) + std::size_t(y)) * std::size_t(nx) +
                      std::size_t(x)];
    }
    /// The interpolated density at `u` in [0, 1]^3 (clamped into it).
    float lookup(Vec3f u) const;
};

/// The maxima of a DensityGrid over a coarse grid of cells covering the same cube. Each cell
/// holds the maximum of every grid value that a lookup inside the cell can read, with one value
/// of margin on every side against rounding at the cell's faces; a trilinear interpolation is
/// a convex combination of the values it reads, so no lookup in a cell exceeds the cell's
/// maximum: the majorant is conservative.
struct MajorantGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<float> maxima;

    float at(int x, int y, int z) const {
        return maxima[(std::size_t(z) * std::size_t(ny) + std::size_t(y)) * std::size_t(nx) +
                      std::size_t(x)];
    }
    /// At most `resolution` cells per axis (fewer where the grid has fewer values).
    static MajorantGrid build(const DensityGrid& grid, int resolution = kResolution);
    static constexpr int kResolution = 16;
};

/// A grid medium's density in the scene: the grid over the box [boxMin, boxMax] (0 outside),
/// with its majorants, built once when the scene is read.
struct GridDensity {
    Vec3f boxMin{0.0f}, boxMax{1.0f};
    DensityGrid density;
    MajorantGrid majorants;

    /// The box's coordinates of a point: boxMin -> 0, boxMax -> 1.
    Vec3f local(const Vec3f& p) const { return (p - boxMin) / (boxMax - boxMin); }
    /// The density at a point of the box.
    float densityAt(const Vec3f& p) const { return density.lookup(local(p)); }
};

}  // namespace lamina::render
