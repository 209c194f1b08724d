// What every kind of camera hands the integrators: a ray, a connection from a scene point to
// the lens (light tracing, BDPT's t = 1), the densities of a ray, a 4x4 matrix.
#pragma once

#include <array>

#include "lamina/core/vector.h"

namespace lamina::render {

struct CameraRay {
    Vec3<float> origin, direction;
    /// What the radiance along the ray is multiplied by: 1 but for a realistic camera (its
    /// lens system's throughput over the density of the ray; 0: vignetted, no ray).
    float weight = 1;
};

/// A connection from a scene point to the lens: a light subpath vertex with throughput beta
/// contributes beta f importance / pdf at `raster`.
struct CameraConnection {
    Vec3<float> lensPoint;
    Vec3<float> wi;  ///< unit, from the scene point towards the lens
    float distance;
    Vec2<float> raster;
    float importance;  ///< We(lensPoint, -wi) (the coefficient of its delta, for a delta camera)
    float pdf;         ///< solid-angle density at the scene point of the lens point (likewise)
};

/// Densities with which a camera, its film position uniform over the whole film, produces a
/// ray: the lens point per unit area and the direction per solid angle.
struct CameraRayPdf {
    float position, direction;
};

/// Row-major 4x4 matrices acting on column vectors (provenance metadata).
using Matrix4 = std::array<float, 16>;

}  // namespace lamina::render
