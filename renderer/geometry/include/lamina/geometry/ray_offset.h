// Robust ray origins: Waechter and Binder 2019, "A Fast and Robust Method for Avoiding
// Self-Intersection" (Ray Tracing Gems, chapter 6). The hit point is moved off the surface
// along the geometric normal by a fixed number of float ULPs (so the offset scales with the
// magnitude of the coordinates, at any scene scale), and by a small absolute amount near the
// origin where ULPs become tiny. That absolute amount stands for the error of hit points in a
// scene of ordinary size; `scale` (Geometry::rayOffsetScale) shrinks or grows it, with the
// region it applies in, for scenes much smaller or larger.
#pragma once

#include <bit>
#include <cstdint>

#include "lamina/core/vector.h"

namespace lamina::render {

/// Offsets p along n (pointing to the side the new ray leaves on), in a scene whose
/// Geometry::rayOffsetScale is `scale` (a power of two).
inline Vec3<float> offsetRayOrigin(const Vec3<float>& p, const Vec3<float>& n, float scale) {
    // The constants of Waechter and Binder's listing 6-1: 1/32 as the switch to the absolute
    // offset, 1/65536 as that offset, 256 ULPs along the normal otherwise.
    const float originRegion = scale / 32.0f;
    const float floatScale = scale / 65536.0f;
    constexpr float kIntScale = 256.0f;
    Vec3<float> out;
    for (int i = 0; i < 3; ++i) {
        const auto ulps = std::int32_t(kIntScale * n[i]);
        const auto bits = std::bit_cast<std::int32_t>(p[i]);
        const float moved = std::bit_cast<float>(bits + (p[i] < 0 ? -ulps : ulps));
        out[i] = std::abs(p[i]) < originRegion ? p[i] + floatScale * n[i] : moved;
    }
    return out;
}

}  // namespace lamina::render
