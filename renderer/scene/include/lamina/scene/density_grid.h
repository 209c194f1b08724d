// A heterogeneous medium's density (docs/media.md, "Grid media"): a grid of values stretched
// over an axis-aligned box, and the coarse grid of its maxima that delta and ratio tracking
// sample against (the majorants).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "lamina/core/vector.h"

namespace lamina::render {

/// nx x ny x nz densities (>= 0, finite) at the centres of the cells of the unit cube, x
/// fastest, then y, then z. Between centres a density is interpolated trilinearly; beyond the
/// outermost centres it is clamped to the nearest one (Mitsuba 3's gridvolume with its default
/// "clamp" wrap), so a grid of one constant is that constant everywhere in the box; or, with
/// `zeroOutside`, the values beyond the grid are 0, so the density fades to 0 over the outer
/// half cell (pbrt-v4's SampledGrid, whose lookups outside the grid read 0).
///
/// A grid read from a file may have 3 channels (an RGB value per cell, `values` holding
/// 3 nx ny nz numbers, the channels of a cell together): lookup() then reads channel 0 only;
/// grid media turn such grids into ColourGrids (colour_grid.h).
struct DensityGrid {
    int nx = 1, ny = 1, nz = 1;
    int channels = 1;
    bool zeroOutside = false;
    std::vector<float> values;

    std::size_t count() const { return std::size_t(nx) * std::size_t(ny) * std::size_t(nz); }
    float at(int x, int y, int z) const {
        return values[((std::size_t(z) * std::size_t(ny) + std::size_t(y)) * std::size_t(nx) +
                       std::size_t(x)) *
                      std::size_t(channels)];
    }
    /// The interpolated density at `u` in [0, 1]^3 (clamped into it).
    float lookup(Vec3f u) const;
};

/// The eight cells a trilinear lookup at `u` in [0, 1]^3 reads in a grid of n = (nx, ny, nz)
/// cells and their weights (summing to 1): with `zeroOutside`, a corner beyond the grid has
/// index -1 (it reads 0); else the indices are clamped into the grid, as DensityGrid::lookup's.
struct TrilinearCorners {
    long index[8];  ///< x + nx (y + ny z), or -1
    float weight[8];
};
TrilinearCorners trilinearCorners(Vec3f u, int nx, int ny, int nz, bool zeroOutside);

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
    /// The same with cx x cy x cz cells (any counts >= 1; the grid's channel 0).
    static MajorantGrid build(const DensityGrid& grid, int cx, int cy, int cz);
    static constexpr int kResolution = 16;
};

struct ColourGrids;
struct CloudDensity;

/// A grid medium's density in the scene: the grid over the box [boxMin, boxMax] (0 outside),
/// with its majorants, built once when the scene is read. The box is given in the medium's own
/// space, which `transformed` media place in the scene by an affine transform (pbrt-v4's
/// renderFromMedium, Mitsuba 3's to_world): rays are taken into medium space once per tracking
/// (toMedium), where the ray parameter t is the same, so distances stay the scene's.
struct GridDensity {
    Vec3f boxMin{0.0f}, boxMax{1.0f};
    DensityGrid density;
    MajorantGrid majorants;
    /// Scene -> medium space, rows of a 3 x 4 matrix (the inverse of the medium's transform).
    bool transformed = false;
    Vec4<float> worldToMedium[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    /// Per-cell RGB coefficients (pbrt-v4's rgbgrid, Mitsuba 3's 3-channel volumes): set, the
    /// medium's coefficients at a point are these grids' values and `density` is unused
    /// (the majorants bound their extinction, in every render mode).
    std::shared_ptr<const ColourGrids> colours;
    /// A procedural density (pbrt-v4's cloud, cloud_density.h): set, it is evaluated at every
    /// lookup instead of `density`, and `majorants` bound it.
    std::shared_ptr<const CloudDensity> cloud;

    /// The box's coordinates of a point: boxMin -> 0, boxMax -> 1.
    Vec3f local(const Vec3f& p) const { return (p - boxMin) / (boxMax - boxMin); }
    /// The density at a point of the box (in medium space).
    float densityAt(const Vec3f& p) const;
    /// A point and a direction of the scene in medium space (unchanged when not transformed).
    Vec3f pointToMedium(const Vec3f& p) const {
        if (!transformed) return p;
        const Vec4<float> h(p, 1.0f);
        return {glm::dot(worldToMedium[0], h), glm::dot(worldToMedium[1], h),
                glm::dot(worldToMedium[2], h)};
    }
    Vec3f directionToMedium(const Vec3f& d) const {
        if (!transformed) return d;
        const Vec4<float> h(d, 0.0f);
        return {glm::dot(worldToMedium[0], h), glm::dot(worldToMedium[1], h),
                glm::dot(worldToMedium[2], h)};
    }
};

}  // namespace lamina::render
