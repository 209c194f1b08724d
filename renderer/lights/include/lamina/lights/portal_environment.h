// An environment seen only through a rectangle of the scene, the opening of a window (pbrt-v4's
// portal on an infinite light; Bitterli, Novak and Jarosz 2015, "Portal-Masked Environment Map
// Sampling"). A ray escaping the scene carries the environment's radiance only if it leaves
// through the rectangle towards the environment's side; every other escaping ray carries
// nothing. In a room closed but for its window this is the plain environment, found far more
// often; in an open scene it is a different light, the one pbrt-v4 renders.
//
// Directions are given by two angles in the rectangle's frame: x along c3 - c0, y along
// c1 - c0, z = x cross y towards the environment. For a unit w = (x, y, z) with z > 0,
//   u = (atan2(x, z) + pi / 2) / pi,   v = (atan2(y, z) + pi / 2) / pi,
// and d omega / d(u, v) = pi^2 (1 - x^2) (1 - y^2) / z (with tan a = x/z, tan b = y/z:
// d omega = da db / r^3 on the plane z = 1, r^2 = 1 + a^2 + b^2, and da = (1 + a^2) pi du).
// Lines of constant x/z and y/z are the rectangle's sides as seen from any point, so from a
// point behind the rectangle the directions through it are exactly the (u, v) of the window
// spanned by the directions to c0 and c2. Next-event estimation samples that window of a
// density proportional to the environment's luminance times the Jacobian (a piecewise-constant
// grid, WindowedDistribution2D); radiance is always the environment's own lookup, so the grid
// only steers samples.
//
// Particles (light tracing, BDPT's light subpaths) cross the rectangle at a point uniform on
// it, along a direction drawn from the whole grid; they start beyond the scene's bounds on that
// line, so geometry outside the window shades them as it shades escaping rays. Their position
// density is per unit area perpendicular to the direction, 1 / (A cos theta), the measure the
// scene disk of other environments uses, which keeps BDPT's vertex at infinity unchanged.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "lamina/core/windowed_distribution_2d.h"
#include "lamina/lights/infinite_lights.h"

namespace lamina::render {

/// The rectangle's frame and the two-angle map of the directions through it.
class PortalMapping {
  public:
    explicit PortalMapping(const std::array<Vec3<double>, 4>& corners);

    /// (u, v) of a direction (world, unit), nullopt on the rectangle's inner side (z <= 0).
    std::optional<Vec2d> toUv(const Vec3d& w) const;
    /// The unit world direction of (u, v) in (0, 1)^2.
    Vec3d fromUv(const Vec2d& uv) const;
    /// d omega / d(u, v) at a unit world direction on the outer side.
    double jacobian(const Vec3d& w) const;
    /// The (u, v) window of the directions from `p` through the rectangle; nullopt unless `p`
    /// lies on the inner side of its plane.
    std::optional<UnitWindow> windowFrom(const Vec3d& p) const;
    /// The rectangle's outward unit normal (towards the environment).
    const Vec3d& normal() const { return z_; }
    /// The point of the rectangle at (s, t) in [0, 1]^2.
    Vec3d pointAt(const Vec2d& st) const;
    double area() const { return area_; }

  private:
    Vec3d corner0_, corner2_, edgeX_, edgeY_;  ///< c0, c2, c3 - c0, c1 - c0
    Vec3d x_, y_, z_;
    double area_ = 0;
};

class PortalEnvironment final : public InfiniteLight {
  public:
    /// `environment` gives the radiance (its origin is ignored); the grid that steers samples
    /// is built from its luminance.
    PortalEnvironment(std::unique_ptr<EnvironmentLight> environment,
                      const std::array<Vec3<double>, 4>& corners, const Geometry& g);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    /// The flux through the rectangle, A times the integral of L cos theta over the hemisphere.
    double power() const override { return power_; }
    Emission environment(const Vec3f& origin, const Vec3f& w) const override;
    float environmentPdf(const Vec3f& origin, const Vec3f& w) const override;
    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const override;

    /// Cells of the steering grid per side: the environment's pixels around the horizon
    /// (pixelsAroundTheHorizon), within these bounds. The grid's u spans pi radians, the
    /// horizon 2 pi, so this is twice the image's angular resolution; a constant environment
    /// gets the smallest grid, which has only the Jacobian to follow.
    static constexpr int kMinResolution = 32, kMaxResolution = 512;

  private:
    std::unique_ptr<EnvironmentLight> environment_;
    PortalMapping mapping_;
    WindowedDistribution2D grid_;
    double power_ = 0;
};

}  // namespace lamina::render
