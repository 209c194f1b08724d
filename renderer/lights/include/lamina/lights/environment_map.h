// An environment map: an RGB image around the scene, importance-sampled by a piecewise-constant
// 2D distribution over its pixels (pbrt-v4 section 12.5.2, in lamina's own code), looked up
// with the nearest pixel (as pbrt-v4's ImageInfiniteLight does), so that the density is
// exactly proportional to the luminance seen in a direction. Directions w point away from the
// scene and are first taken into the map's frame: w_map = R_y(rotate)^-1 T^-1 w, with T the
// light's `transform` (orthogonal: a rotation or a reflection) and R_y the right-handed
// rotation about +y by `rotate` degrees. In the map's frame:
//   equirectangular        u = 1/2 + atan2(x, z) / (2 pi), v = acos(y) / pi (v = 0 at the
//                          zenith, the top row; y up); density p(u, v) / (2 pi^2 sin(theta)),
//                          p proportional to luminance x sin(theta);
//   equal_area_octahedral  (u, v) = equalAreaSphereToSquare(w_map) (equal_area_sphere.h:
//                          pbrt-v4's convention; the centre of the square is +z, u = column
//                          from the left follows x, v = row from the top follows y), square
//                          images only; density p(u, v) / (4 pi), p proportional to luminance.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

/// A piecewise-constant density on [0, 1).
class PiecewiseConstant1D {
  public:
    explicit PiecewiseConstant1D(std::vector<double> f);
    /// x in [0, 1), its density, and the cell index.
    double sample(double u, double& pdf, int& cell) const;
    double pdf(double x) const;
    double integral() const { return integral_; }
    int size() const { return int(f_.size()); }

  private:
    std::vector<double> f_, cdf_;
    double integral_ = 0;
};

/// How an image lies on the sphere and how it is turned in the world.
struct EnvironmentLayout {
    EnvironmentMapping mapping = EnvironmentMapping::Equirectangular;
    double rotateDegrees = 0;       ///< about +y, first
    Mat3<double> orientation{1.0};  ///< then this orthogonal matrix
};

class EnvironmentMap {
  public:
    /// Loads an image (EXR through OpenEXR; HDR, PNG, ... through lamina's OpenImageIO module,
    /// image_input.h); InputError if it cannot, or
    /// if an equal-area octahedral image is not square.
    EnvironmentMap(const std::filesystem::path& file, const EnvironmentLayout& layout);
    /// An image in memory, rows from the top (tests).
    EnvironmentMap(int width, int height, std::vector<Rgb<float>> pixels,
                   const EnvironmentLayout& layout);

    Rgb<float> lookup(const Vec3<float>& w) const;
    /// A direction drawn with density pdf(w).
    Vec3<float> sample(const Vec2<float>& u, float& pdf) const;
    float pdf(const Vec3<float>& w) const;
    /// Pixels along the horizon: the width of an equirectangular image, the perimeter of the
    /// equator's diamond (2 sqrt 2 times the side) in an equal-area octahedral one.
    int pixelsAroundTheHorizon() const;
    /// Mean luminance over the sphere (solid-angle weighted).
    double averageLuminance() const { return average_; }

  private:
    void build(const EnvironmentLayout& layout);
    Vec2<double> toUv(const Vec3<float>& w) const;
    Vec3<float> fromUv(double u, double v) const;
    /// Steradians per unit area of the image's [0, 1]^2 at row v (0 at the poles).
    double solidAnglePerArea(double v) const;

    EnvironmentMapping mapping_ = EnvironmentMapping::Equirectangular;
    int width_ = 0, height_ = 0;
    std::vector<Rgb<float>> pixels_;
    /// Row i of T R_y, and of its inverse (its transpose).
    Vec3<double> worldFromMap_[3], mapFromWorld_[3];
    std::vector<PiecewiseConstant1D> rows_;
    std::unique_ptr<PiecewiseConstant1D> marginal_;
    double average_ = 0;
};

}  // namespace lamina::render
