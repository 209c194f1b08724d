#include "lamina/scene/density_grid.h"

#include <algorithm>
#include <cmath>

namespace lamina::render {

namespace {

/// Where coordinate `v` of [0, 1] falls between the centres of `n` cells: the two values it
/// interpolates (clamped to the grid) and the weight of the second.
struct Between {
    int i0, i1;
    float f;
};

Between between(float v, int n) {
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

}  // namespace

float DensityGrid::lookup(Vec3f u) const {
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

MajorantGrid MajorantGrid::build(const DensityGrid& grid, int resolution) {
    MajorantGrid m;
    m.nx = std::min(resolution, grid.nx);
    m.ny = std::min(resolution, grid.ny);
    m.nz = std::min(resolution, grid.nz);
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
