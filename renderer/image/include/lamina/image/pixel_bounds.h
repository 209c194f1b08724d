// A rectangle of pixels: a film's window, an EXR's data window, a shard's crop.
#pragma once

namespace lamina::render {

/// Half-open pixel bounds [x0, x1) x [y0, y1), like pbrt's --pixelbounds.
struct PixelBounds {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool overlaps(const PixelBounds& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
    bool operator==(const PixelBounds&) const = default;
};

}  // namespace lamina::render
