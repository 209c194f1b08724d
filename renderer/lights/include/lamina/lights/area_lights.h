// Area lights: emitting shapes. Each one draws a point uniformly by area (samplePoint), from
// which AreaLight writes the particle emission, the area density and the sampling by area;
// rectangles and spheres sample the solid angle they subtend instead where that is accurate.
// Triangles work in single precision, rectangles, disks and spheres in double.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "lamina/lights/lights.h"

namespace lamina::render {

/// What every emitting surface shares: its colour, one- or two-sided emission, and a power
/// of (1 or 2) pi A L for area A and radiance L.
class AreaLight : public Light {
  public:
    /// A point by area (samplePoint), its density converted to solid angle at `ref`.
    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    /// The density of sampling by area, in solid angle at `ref`.
    float pdf(const Vec3f& ref, const SurfaceHit& onLight) const override;
    Emission radiance(const SurfaceHit& hit, const Vec3f& w) const override;
    double power() const override;

    /// Particles: a point uniform by area, a cosine-distributed direction about the normal
    /// (on a side chosen with probability 1/2 when two-sided).
    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const override;

  protected:
    struct AreaPoint {
        Vec3d p, n;  ///< the point and the front normal
    };
    /// A point uniform by area.
    virtual AreaPoint samplePoint(const Vec2f& u) const = 0;
    /// The bounds of a flat light in box [lower, upper] with front normal `n`: its normal as
    /// the axis (theta_o = 0), emission over the hemisphere (theta_e = pi/2), intensity L A.
    LightBounds flatBounds(const Vec3f& lower, const Vec3f& upper, const Vec3f& n) const;
    /// The luminance of the radiance.
    float radianceLuminance() const;

    AreaLight(const EmissionDesc& e, double area);

    /// The density, in solid angle at `ref`, of drawing `a` by area (double precision); 0
    /// when the surface is seen edge-on.
    double solidAngleDensity(const Vec3d& ref, const AreaPoint& a) const;
    /// The sample towards `p` (front normal `n`) drawn with solid-angle density `pdf`;
    /// nullopt when it is degenerate or, for a one-sided light, seen from behind.
    std::optional<LightSample> towards(const Vec3d& ref, const Vec3d& p, const Vec3d& n,
                                       double pdf) const;

    bool twoSided_;
    EmitterColor color_;
    double area_;
};

/// One emitting triangle of a mesh, sampled uniformly by area.
class TriangleLight final : public AreaLight {
  public:
    TriangleLight(const MeshDesc& mesh, std::size_t triangle);

    std::optional<LightBounds> bounds() const override;

  private:
    AreaPoint samplePoint(const Vec2f& u) const override;

    Vec3f p0_, p1_, p2_, n_;
};

/// An emitting rectangle, sampled uniformly in the solid angle it subtends (Urena, Fajardo
/// and King 2013, "An Area-Preserving Parametrization for Spherical Rectangles", EGSR; the
/// algorithm of their section 4, in double precision) from points nearer its plane than its
/// diagonal is long, and by area from farther away or when the solid angle is too small for
/// the spherical quantities to be accurate (below 1e-4 sr they cancel).
class RectangleLight final : public AreaLight {
  public:
    explicit RectangleLight(const MeshDesc& mesh);

    /// A mesh of four vertices and two triangles that together are a rectangle: split along
    /// either diagonal, the triangles in any order, both facing the same side. A `rectangle`
    /// shape, a mesh of one four-cornered face with right angles such as the Cornell box's
    /// lamp, a pbrt-v4 bilinear patch. It is one light, not two triangles: sampled by the
    /// solid angle it subtends, and with nothing for the light BVH to choose between.
    static bool isRectangle(const MeshDesc& m);

    /// The four vertices of two triangles that form one quad, in the order of its boundary
    /// from vertex 0 towards its lower-numbered neighbour ((0, 1, 2, 3) for the fan of the
    /// face (0, 1, 2, 3), mirrored or not); none when the triangles do not share exactly one
    /// edge, or run along it the same way (they would face opposite sides).
    using QuadCorners = std::array<std::uint32_t, 4>;
    static std::optional<QuadCorners> quadCorners(const MeshDesc& m);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    float pdf(const Vec3f& ref, const SurfaceHit& hit) const override;
    std::optional<LightBounds> bounds() const override;

  private:
    AreaPoint samplePoint(const Vec2f& u) const override;

    static constexpr double kMinSolidAngle = 1e-4;

    /// The signed distance of `ref` from the rectangle's plane, positive on its front.
    double height(const Vec3d& ref) const;
    /// Whether a point at `height` from the plane is nearer it than the diagonal is long: only
    /// there does the area density vary enough over the rectangle (its cosine and squared distance)
    /// to pay for the solid-angle map's four arccosines and a sine. Sampled by solid angle
    /// from everywhere, the Cornell box took 18% more time for 8% less variance per sample.
    /// Cycles 3.4 makes the same choice for triangles, with their longest edge
    /// (kernel/light/triangle.h).
    bool bySolidAngle(double height) const { return diagonal2_ > height * height; }

    // The rectangle seen from `ref`, in the local frame of the paper (z towards the plane).
    struct Spherical {
        Vec3d x, y, z;
        double x0, x1, y0, y1, z0;
        double b0, b1, k, solidAngle = 0;
    };
    Spherical spherical(const Vec3d& ref) const;

    Vec3d corner_, x_, y_, n_;
    double lx_ = 0, ly_ = 0, diagonal2_ = 0;
    /// The distance from the plane within which a point is taken to lie in it.
    double planeTolerance_ = 0;
};

/// An emitting disk, sampled uniformly by area (the concentric mapping) in double precision.
class DiskLight final : public AreaLight {
  public:
    explicit DiskLight(const DiskDesc& d);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    std::optional<LightBounds> bounds() const override;

  private:
    AreaPoint samplePoint(const Vec2f& u) const override;

    DiskDesc disk_;
    Frame<double> frame_;
};

/// An emitting sphere: sampled uniformly in the cone it subtends when seen from outside
/// (emitting outwards), uniformly by area otherwise.
class SphereLight final : public AreaLight {
  public:
    explicit SphereLight(const SphereDesc& s);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    float pdf(const Vec3f& ref, const SurfaceHit& hit) const override;
    /// Its box, normals in every direction (theta_o = pi) and intensity L pi r^2 (the
    /// projected area seen from outside).
    std::optional<LightBounds> bounds() const override;

  private:
    AreaPoint samplePoint(const Vec2f& u) const override;

    // The cone is only valid for points outside; an inward-emitting sphere is seen from
    // inside, where its whole surface is visible.
    bool useCone(double dc2) const;

    SphereDesc sphere_;
};

/// An emitting partial sphere, cylinder or partial disk (QuadricDesc), sampled uniformly by
/// area in double precision (sampleQuadric, quadric.h). pbrt-v4 samples a partial sphere and
/// disk over the whole shape with the density of the clipped one (Sphere::Sample, Disk::Sample);
/// here every point lies on the clipped shape.
class QuadricLight final : public AreaLight {
  public:
    explicit QuadricLight(const QuadricDesc& q);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    /// Its box; a disk's normal and intensity L A as any flat light, a sphere's or a
    /// cylinder's normals in every direction (theta_o = pi) and intensity L times its largest
    /// projected area, bounded by its area and the silhouette of the whole shape (pi r^2, or
    /// 2 r (z_max - z_min)).
    std::optional<LightBounds> bounds() const override;

  private:
    AreaPoint samplePoint(const Vec2f& u) const override;

    QuadricDesc quadric_;
};

}  // namespace lamina::render
