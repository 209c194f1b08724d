// A `curves` shape in Embree (CurvesDesc): round tubes as RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE
// (a swept circle, a real surface seen from outside and from inside), flat ribbons facing the
// ray as RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE; and the surface at a hit, with the curve's tangent
// for the shading frame (the hair BSDF's fibre axis).
#pragma once

#include <embree3/rtcore.h>

#include "lamina/geometry/geometry.h"

namespace lamina::render {

/// The Embree geometry of `c` on `device` (not yet committed).
RTCGeometry newCurvesGeometry(RTCDevice device, const CurvesDesc& c);

/// The surface of `c` at Embree's hit `h` of the ray (origin, direction) at hit.t: the point
/// on the tube, its outward normal (a tube) or, on a flat ribbon, the ribbon's normal towards
/// the ray with the shading normal of the tube the ribbon stands for (pbrt-v4's cylinder look),
/// the tangent, and uv = (u along the strand's segment, v across: 0.5 on the axis).
void curveSurfaceAt(const CurvesDesc& c, const Vec3<double>& origin, const Vec3<double>& direction,
                    const RTCHit& h, SurfaceHit& hit);

}  // namespace lamina::render
