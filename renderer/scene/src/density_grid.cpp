#include "lamina/scene/density_grid.h"

#include <algorithm>
#include <cmath>

#include "lamina/scene/cloud_density.h"

namespace lamina::render {

namespace {

/// Where coordinate `v` of [0, 1] falls between the centres of `n` cells: the two values it
/// interpolates (clamped to the grid) and the weight of the second.
struct Between {
    int i0, i1;
    float f;
};

[[gnu::always_inline]] inline Between between(float v, int n) {
    v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // also a NaN to 0
    const float s = v * float(n) - 0.5f;
    const float below = std::floor(s);
    const int i = int(below);
    return {std::clamp(i, 0, n - 1), std::clamp(i + 1, 0, n - 1), s - below};
}

/// The grid values a lookup in coarse cell `c` of `cells` along an axis of `n` values can read
/// (Between's i0 and i1 over the cell), widened by one on each side: [first, last].
std::pair<int, int> support(int c, int cells, int n) {
    const double a = double(c) / cells * n - 0.5, b = double(c + 1) / cells * n - 0.5;
    return {std::max(int(std::floor(a)) - 1, 0), std::min(int(std::floor(b)) + 2, n - 1)};
}

/// Where `v` of [0, 1] falls between the centres of `n` cells when the values beyond the grid
/// are 0: the two cells (-1 or n beyond it) and the weight of the second.
[[gnu::always_inline]] inline Between betweenUnclamped(float v, int n) {
    v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
    const float s = v * float(n) - 0.5f;
    const float below = std::floor(s);
    return {int(below), int(below) + 1, s - below};
}

}  // namespace

TrilinearCorners trilinearCorners(Vec3f u, int nx, int ny, int nz, bool zeroOutside) {
    const auto axis = [&](float v, int n) {
        return zeroOutside ? betweenUnclamped(v, n) : between(v, n);
    };
    const Between x = axis(u.x, nx), y = axis(u.y, ny), z = axis(u.z, nz);
    TrilinearCorners c;
    for (int k = 0; k < 8; ++k) {
        const int i = k & 1 ? x.i1 : x.i0, j = k & 2 ? y.i1 : y.i0, l = k & 4 ? z.i1 : z.i0;
        const bool inside = i >= 0 && i < nx && j >= 0 && j < ny && l >= 0 && l < nz;
        c.index[k] = inside ? long(i) + long(nx) * (long(j) + long(ny) * long(l)) : -1;
        c.weight[k] =
            (k & 1 ? x.f : 1.0f - x.f) * (k & 2 ? y.f : 1.0f - y.f) * (k & 4 ? z.f : 1.0f - z.f);
    }
    return c;
}

float DensityGrid::lookup(Vec3f u) const {
    if (zeroOutside) {
        // pbrt-v4's lookups beyond the grid read 0. The lerps are clamped as below.
        const Between x = betweenUnclamped(u.x, nx), y = betweenUnclamped(u.y, ny),
                      z = betweenUnclamped(u.z, nz);
        const auto value = [&](int i, int j, int k) {
            return i < 0 || i >= nx || j < 0 || j >= ny || k < 0 || k >= nz ? 0.0f : at(i, j, k);
        };
        const auto lerp = [](float a, float b, float f) {
            return std::clamp((1.0f - f) * a + f * b, std::min(a, b), std::max(a, b));
        };
        const auto row = [&](int j, int k) {
            return lerp(value(x.i0, j, k), value(x.i1, j, k), x.f);
        };
        const auto plane = [&](int k) { return lerp(row(y.i0, k), row(y.i1, k), y.f); };
        return lerp(plane(z.i0), plane(z.i1), z.f);
    }
    const Between x = between(u.x, nx), y = between(u.y, ny), z = between(u.z, nz);
    // Clamped to the two values: rounding cannot take an interpolation above the larger, which
    // the majorants assume.
    const auto lerp = [](float a, float b, float f) {
        return std::clamp((1.0f - f) * a + f * b, std::min(a, b), std::max(a, b));
    };
    const auto row = [&](int j, int k) { return lerp(at(x.i0, j, k), at(x.i1, j, k), x.f); };
    const auto plane = [&](int k) { return lerp(row(y.i0, k), row(y.i1, k), y.f); };
    return lerp(plane(z.i0), plane(z.i1), z.f);
}

float GridDensity::densityAt(const Vec3f& p) const {
    return cloud ? cloud->at(p) : density.lookup(local(p));
}

MajorantGrid MajorantGrid::build(const DensityGrid& grid, int resolution) {
    return build(grid, std::min(resolution, grid.nx), std::min(resolution, grid.ny),
                 std::min(resolution, grid.nz));
}

MajorantGrid MajorantGrid::build(const DensityGrid& grid, int cellsX, int cellsY, int cellsZ) {
    MajorantGrid m;
    m.nx = cellsX;
    m.ny = cellsY;
    m.nz = cellsZ;
    m.maxima.resize(std::size_t(m.nx) * std::size_t(m.ny) * std::size_t(m.nz));
    std::size_t out = 0;
    for (int cz = 0; cz < m.nz; ++cz) {
        const auto [z0, z1] = support(cz, m.nz, grid.nz);
        for (int cy = 0; cy < m.ny; ++cy) {
            const auto [y0, y1] = support(cy, m.ny, grid.ny);
            for (int cx = 0; cx < m.nx; ++cx) {
                const auto [x0, x1] = support(cx, m.nx, grid.nx);
                float maximum = 0.0f;
                for (int z = z0; z <= z1; ++z)
                    for (int y = y0; y <= y1; ++y)
                        for (int x = x0; x <= x1; ++x)
                            maximum = std::max(maximum, grid.at(x, y, z));
                m.maxima[out++] = maximum;
            }
        }
    }
    return m;
}

}  // namespace lamina::render
