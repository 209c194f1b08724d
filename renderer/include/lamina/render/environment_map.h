// An environment map: an equirectangular (latitude-longitude) RGB image around the scene, y up,
// importance-sampled by a piecewise-constant 2D distribution proportional to luminance x
// sin(theta) (pbrt-v4 section 12.5.2, in lamina's own code). Directions w point away from the
// scene: u = 1/2 + atan2(w.x, w.z) / (2 pi) (after the map's rotation about +y), v =
// acos(w.y) / pi (v = 0 at the zenith); the density of a direction is
// p(u, v) / (2 pi^2 sin(theta)).
#pragma once

#include <filesystem>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

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

class EnvironmentMap {
  public:
    /// Loads an image (EXR, HDR, PNG, ... through OpenImageIO); InputError if it cannot.
    EnvironmentMap(const std::filesystem::path& file, double rotationDegrees);
    /// A constant image (tests).
    EnvironmentMap(int width, int height, std::vector<Rgb<float>> pixels, double rotationDegrees);

    Rgb<float> lookup(const Vec3<float>& w) const;
    /// A direction drawn with density pdf(w).
    Vec3<float> sample(const Vec2<float>& u, float& pdf) const;
    float pdf(const Vec3<float>& w) const;
    /// Mean luminance over the sphere (solid-angle weighted).
    double averageLuminance() const { return average_; }

  private:
    void build(double rotationDegrees);
    Vec2<double> toUv(const Vec3<float>& w) const;
    Vec3<float> fromUv(double u, double v) const;

    int width_ = 0, height_ = 0;
    std::vector<Rgb<float>> pixels_;
    double cosRot_ = 1, sinRot_ = 0;
    std::vector<PiecewiseConstant1D> rows_;
    std::unique_ptr<PiecewiseConstant1D> marginal_;
    double average_ = 0;
};

}  // namespace lamina::render
