// A vertex of a BDPT subpath (Veach 1997, section 10.2): where it is, what it scatters or
// emits with, its throughput from the subpath's start, and the forward and reverse area
// densities the MIS weights are computed from; and the two geometric helpers on vertices.
#pragma once

#include <cmath>

#include "lamina/core/spectrum.h"
#include "lamina/geometry/geometry.h"

namespace lamina::render {

enum class BdptVertexType { Camera, Light, Surface };

template <SpectrumType S>
struct BdptVertex {
    BdptVertexType type = BdptVertexType::Surface;
    Vec3f p{0.0f}, ng{0.0f}, ns{0.0f};
    Vec2f uv{0.0f};
    int material = -1;
    int light = -1;           ///< the light of an emitter (Light vertices, emissive surfaces)
    bool infinite = false;    ///< a Light vertex at infinity; `p` holds its direction
    bool deltaLight = false;  ///< a Light vertex with a delta position or direction
    bool delta = false;       ///< scattered by a delta lobe
    S beta{0.0f};
    float pdfFwd = 0, pdfRev = 0;  ///< area densities (solid angle for infinite vertices)

    /// Surfaces and area-light points (not lenses, point lights or infinity).
    bool onSurface() const { return !infinite && ng != Vec3f(0.0f); }
};

/// Converts a solid-angle density at `from` towards `to` into an area density at `to`.
template <SpectrumType S>
float toArea(float pdfSolidAngle, const BdptVertex<S>& from, const BdptVertex<S>& to) {
    if (to.infinite) return pdfSolidAngle;
    const Vec3f d = to.p - from.p;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return 0.0f;
    float pdf = pdfSolidAngle / dist2;
    if (to.onSurface()) pdf *= std::abs(glm::dot(to.ng, d)) / std::sqrt(dist2);
    return pdf;
}

/// The unit direction from one vertex to another (either may be at infinity).
template <SpectrumType S>
Vec3f directionTo(const BdptVertex<S>& from, const BdptVertex<S>& to) {
    if (to.infinite) return to.p;
    if (from.infinite) return -from.p;
    return glm::normalize(to.p - from.p);
}

}  // namespace lamina::render
