// A vertex of a BDPT subpath (Veach 1997, section 10.2): where it is, what it scatters or
// emits with, its throughput from the subpath's start, and the forward and reverse area
// densities the MIS weights are computed from; and the two geometric helpers on vertices.
// A medium vertex (a scattering event in a homogeneous medium, docs/media.md) has no normal:
// its area density is Veach's with |cos| = 1 (pbrt-v4's BDPT converts densities the same way).
// A light subpath may start in an emitting medium's volume (a Light vertex with `volume`), and
// a camera subpath's medium vertex in an emitting medium carries its own emission (s = 0):
// docs/media.md, "Emitting media in light tracing and BDPT".
#pragma once

#include <cmath>

#include "lamina/core/spectrum.h"
#include "lamina/geometry/geometry.h"

namespace lamina::render {

enum class BdptVertexType { Camera, Light, Surface, Medium };

template <SpectrumType S>
struct BdptVertex {
    BdptVertexType type = BdptVertexType::Surface;
    Vec3f p{0.0f}, ng{0.0f}, ns{0.0f};
    Vec2f uv{0.0f};
    Vec3f tangent{0.0f};  ///< a curve's (SurfaceHit::tangent): the shading frame's x
    int material = -1;
    int light = -1;           ///< the light of an emitter (Light vertices, emissive surfaces)
    bool infinite = false;    ///< a Light vertex at infinity; `p` holds its direction
    bool deltaLight = false;  ///< a Light vertex with a delta position or direction
    bool volume = false;      ///< a Light vertex in the volume of emitting medium `medium`
    bool delta = false;       ///< scattered by a delta lobe
    S beta{0.0f};
    float pdfFwd = 0, pdfRev = 0;  ///< area densities (solid angle for infinite vertices)
    // With media (medium_transport.h):
    int shape = -1;   ///< the shape of a Surface vertex (its boundary's media)
    int medium = -1;  ///< the medium the subpath arrived in (a Medium vertex's own)
    float g = 0;      ///< a Medium vertex's Henyey-Greenstein asymmetry
    /// The subpath's densities per channel up to this vertex relative to its hero's (the
    /// spectral MIS ratios rU of medium_transport.h); 1 without media.
    S rU{1.0f};
    /// A camera subpath's Medium vertex in an emitting medium: the medium's emission there as
    /// the subpath reached it (its throughput before the collision times T sigma_a Le / p, the
    /// collision estimator of MediumFlight::apply), to be weighted over the channels by rU.
    S emission{0.0f};

    /// Surfaces and area-light points (not lenses, point lights, medium vertices or infinity).
    bool onSurface() const { return !infinite && ng != Vec3f(0.0f); }
    /// A vertex that scatters: what a connection can join (neither end of the path).
    bool scatters() const {
        return type == BdptVertexType::Surface || type == BdptVertexType::Medium;
    }
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
