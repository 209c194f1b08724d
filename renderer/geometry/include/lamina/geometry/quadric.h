// pbrt-v4's quadrics (QuadricDesc: a partial sphere, a cylinder, a partial disk) in double
// precision: the intersections of a ray, the surface at a point (pbrt-v4's uv, the normal and
// the tangents) and points uniform by area. The Embree user geometry of geometry.cpp
// intersects them with these functions, Geometry::intersect rebuilds the surface with them, and
// their area lights sample them (area_lights.h).
#pragma once

#include "lamina/scene/shape_description.h"

namespace lamina::render {

/// A ray's intersection with a quadric: its distance in units of the ray's direction, and the
/// point in the quadric's frame, projected onto the surface.
struct QuadricHit {
    double t = 0;
    Vec3d local{0.0};
};

/// The intersections of o + t d (in the shape's space) with t in (tMin, tMax) that lie within
/// the quadric's clipping, nearest first, into `hits`; returns how many (at most 2). The
/// roots come from the quadratic in its stable form (Press et al., "Numerical Recipes", 5.6;
/// the discriminant as pbrt-v4 forms it, from the ray's closest point to the centre or axis,
/// to keep its precision for rays that pass far away), each point projected back onto the
/// surface before it is clipped, as pbrt-v4's BasicIntersect does.
int intersectQuadric(const QuadricDesc& q, const Vec3d& o, const Vec3d& d, double tMin, double tMax,
                     QuadricHit hits[2]);

/// The surface at a point of the quadric, in the shape's space.
struct QuadricSurface {
    Vec3d p{0.0};  ///< on the surface
    Vec3d n{0.0};  ///< unit: away from the axis (sphere, cylinder) or +z (disk), or flipped
    /// pbrt-v4's: u = phi / phi_max; v = (theta - theta(z_min)) / (theta(z_max) -
    /// theta(z_min)) on the sphere (theta = acos(z / r)), (z - z_min) / (z_max - z_min) on
    /// the cylinder, (r - rho) / (r - r_inner) on the disk.
    Vec2<double> uv{0.0};
    /// dp/du, dp/dv and dn/du, dn/dv for that uv (pbrt-v4's, with the normal's derivatives
    /// of the sphere and the cylinder in closed form: n = p / r and (x, y, 0) / r); all zero
    /// where u is undefined (the axis: a sphere's pole, a disk's centre).
    Vec3d dpdu{0.0}, dpdv{0.0}, dndu{0.0}, dndv{0.0};
};

/// The surface at `local` (a point of the frame on or near the surface: projected onto it).
QuadricSurface quadricSurface(const QuadricDesc& q, const Vec3d& local);

/// The unit normal (QuadricSurface::n) at a point of the frame on the surface, in the shape's
/// space: what quadricSurface gives without the rest.
Vec3d quadricNormal(const QuadricDesc& q, const Vec3d& local);

/// A point of the quadric uniform by area, in its frame: phi = u.y phi_max, and z = lerp(u.x,
/// z_min, z_max) on the sphere (Archimedes' hat-box theorem: a sphere's area is uniform in z)
/// and the cylinder, rho^2 = lerp(u.x, r_inner^2, r^2) on the disk.
Vec3d sampleQuadric(const QuadricDesc& q, const Vec2<double>& u);

}  // namespace lamina::render
