// The equal-area octahedral mapping between the unit square and the unit sphere (Clarberg
// 2008, "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD"; the convention of pbrt-v4's
// EqualAreaSquareToSphere / EqualAreaSphereToSquare, section 3.8.3, in lamina's own code):
// the centre of the square is +z, its corners -z, the square's diamond |2u-1| + |2v-1| = 1 the
// equator; the sign of x follows 2u - 1 and the sign of y follows 2v - 1. Equal areas of the
// square map to equal solid angles: a region of area A covers 4 pi A steradians.
#pragma once

#include "lamina/core/vector.h"

namespace lamina::render {

/// (u, v) in [0, 1]^2 -> a unit vector.
Vec3d equalAreaSquareToSphere(const Vec2d& uv);
/// A unit vector -> (u, v) in [0, 1]^2 (the inverse of equalAreaSquareToSphere).
Vec2d equalAreaSphereToSquare(const Vec3d& w);

}  // namespace lamina::render
