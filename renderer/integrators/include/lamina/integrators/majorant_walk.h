// The majorant grid along a ray (docs/media.md, "Grid media"): the pieces of a ray inside a grid
// medium's box, one per cell of its majorant grid, in order, by Amanatides and Woo's traversal
// (1987, "A fast voxel traversal algorithm for ray tracing"), as pbrt-v4's DDAMajorantIterator
// walks its majorant grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "lamina/scene/density_grid.h"

namespace lamina::render {

/// Calls `segment(t0, t1, maximum)` for the consecutive pieces [t0, t1] of the ray o + t d,
/// t in [0, tMax] (tMax may be infinite), inside the grid's box, each within one majorant cell
/// whose maximum density is `maximum`; stops when `segment` returns false.
template <typename Segment>
void walkMajorants(const GridDensity& grid, const Vec3f& o, const Vec3f& d, float tMax,
                   Segment&& segment) {
    const MajorantGrid& m = grid.majorants;
    const int cells[3] = {m.nx, m.ny, m.nz};
    // The ray in units of majorant cells (the same parameter t).
    const Vec3f extent = grid.boxMax - grid.boxMin;
    const Vec3f go = (o - grid.boxMin) / extent * Vec3f(float(m.nx), float(m.ny), float(m.nz));
    const Vec3f gd = d / extent * Vec3f(float(m.nx), float(m.ny), float(m.nz));
    float t0 = 0.0f, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        if (gd[a] == 0.0f) {
            if (!(go[a] >= 0.0f && go[a] <= float(cells[a]))) return;
            continue;
        }
        float ta = -go[a] / gd[a], tb = (float(cells[a]) - go[a]) / gd[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return;
    int cell[3], step[3];
    float next[3], delta[3];
    for (int a = 0; a < 3; ++a) {
        const float p = go[a] + gd[a] * t0;
        cell[a] = std::clamp(int(std::floor(p)), 0, cells[a] - 1);
        if (gd[a] > 0.0f) {
            next[a] = t0 + (float(cell[a] + 1) - p) / gd[a];
            delta[a] = 1.0f / gd[a];
            step[a] = 1;
        } else if (gd[a] < 0.0f) {
            next[a] = t0 + (float(cell[a]) - p) / gd[a];
            delta[a] = -1.0f / gd[a];
            step[a] = -1;
        } else {
            next[a] = delta[a] = std::numeric_limits<float>::infinity();
            step[a] = 0;
        }
    }
    for (float t = t0;;) {
        const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        const float end = std::min(next[a], t1);
        if (end > t && !segment(t, end, m.at(cell[0], cell[1], cell[2]))) return;
        if (!(next[a] < t1)) return;
        t = std::max(t, end);
        cell[a] += step[a];
        if (cell[a] < 0 || cell[a] >= cells[a]) return;
        next[a] += delta[a];
    }
}

}  // namespace lamina::render
