// Grids of RGB coefficients (docs/media.md, "Grid media"): a medium whose colour varies in
// space, pbrt-v4's rgbgrid (a sigma_a and a sigma_s value per cell) and Mitsuba 3's 3-channel
// grid volumes. Each cell holds its coefficient as linear Rec.709 RGB for RGB mode and as the
// unbounded spectrum spectral mode upsamples it to (pbrt-v4's RGBUnboundedSpectrum, as
// homogeneous media upsample their coefficients): scale 2 max(rgb) times the sigmoid
// polynomial of rgb / scale (Jakob and Hanika 2019). A lookup interpolates the eight cells'
// values trilinearly, the spectra at the path's wavelengths (as pbrt-v4's RGBGridMedium
// interpolates its cells' spectra).
#pragma once

#include <array>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/scene/density_grid.h"

namespace lamina::render {

struct ColourGrid {
    int nx = 1, ny = 1, nz = 1;
    bool zeroOutside = false;  ///< as DensityGrid's
    std::vector<Rgb<float>> rgb;
    /// Per cell: the polynomial's c0, c1, c2 (nm) and the spectrum's scale.
    std::vector<std::array<float, 4>> spectral;

    /// `g`'s values (1 channel: grey, 3: RGB) times `factor` per channel (all >= 0), with
    /// `g`'s size and edges.
    static ColourGrid fromGrid(const DensityGrid& g, const Rgb<double>& factor);
    /// One cell of `value` (clamped edges: the constant everywhere in the box).
    static ColourGrid constant(const Rgb<double>& value);

    Rgb<float> lookupRgb(Vec3f u) const;
    /// The interpolated spectrum at the n wavelengths `lambda` (nm) into `out`.
    void lookupSpectral(Vec3f u, const float* lambda, int n, float* out) const;
    /// An upper bound of cell i's value over the RGB channels and over 360-830 nm.
    float bound(std::size_t i) const { return bounds_[i]; }

  private:
    void finish();
    std::vector<float> bounds_;
};

/// A grid medium's per-cell coefficients, in 1 / scene unit (the file's scale included).
struct ColourGrids {
    ColourGrid sigmaA, sigmaS;
    /// The majorants of sigma_a + sigma_s over the box: cells of the finer of the two grids'
    /// majorant resolutions, each the sum of the two grids' largest bounds there.
    MajorantGrid majorants() const;
};

}  // namespace lamina::render
