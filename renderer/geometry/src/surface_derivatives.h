// dp/du, dp/dv, dn/du, dn/dv at a hit, one function per kind of shape, in the shape's own space
// (the world, or its object's), for the uv that geometry.cpp gives each kind. Asked only for a
// shape whose material turns the shading normal (shading_normal_maps.h).
#pragma once

#include <cstdint>

#include "lamina/geometry/geometry.h"

namespace lamina::render {

/// A triangle's (pbrt-v4 book section 6.5.3): from the differences of its uvs (the
/// barycentric (b1, b2) when the mesh has none), the derivatives of the interpolated vertex
/// normal (unnormalised, as pbrt-v4 takes them) where it has normals. `hit`: the surface
/// geometry.cpp made at barycentrics (b1, b2) of `triangle`.
SurfaceDerivatives surfaceDerivatives(const MeshDesc& m, std::uint32_t triangle, float b1, float b2,
                                      const SurfaceHit& hit);
/// u = phi / 2 pi + 1/2, v = theta / pi: dp/du = 2 pi (-y, x, 0), dp/dv = pi r (cos theta cos
/// phi, cos theta sin phi, -sin theta) about the centre, dn = dp / r (negated for a sphere
/// whose normals face inwards); zero at the poles.
SurfaceDerivatives surfaceDerivatives(const SphereDesc& s, const SurfaceHit& hit);
/// u = rho / radius, v = phi / 2 pi + 1/2 in the disk's frame: dp/du = radius (cos phi, sin
/// phi), dp/dv = 2 pi rho (-sin phi, cos phi); zero at the centre; a flat normal.
SurfaceDerivatives surfaceDerivatives(const DiskDesc& d, const SurfaceHit& hit);
/// pbrt-v4's for its uv (quadricSurface, quadric.h).
SurfaceDerivatives surfaceDerivatives(const QuadricDesc& q, const SurfaceHit& hit);
/// None for curves: a bump or normal map leaves a curve's normal as it is (its uv runs along
/// one segment, not over a surface a map could cover).
inline SurfaceDerivatives surfaceDerivatives(const CurvesDesc&, const SurfaceHit&) {
    return {};
}

}  // namespace lamina::render
