// Lights at infinity: a directional light, a constant environment and an image environment
// (environment_map.h). InfiniteLight owns the disk their particles start on; an
// EnvironmentLight needs only a way to draw an arriving direction and writes the rest of its
// sampling (next-event and particles) from it.
#pragma once

#include "lamina/lights/environment_map.h"
#include "lamina/lights/lights.h"

namespace lamina::render {

/// Particles from infinite lights start on a disk of the scene's bounding radius, centred
/// on the bounding sphere's tangent plane on the light's side and perpendicular to their
/// direction, so every one of them crosses the scene's bounds (pbrt-v4 section 12.5).
struct SceneDisk {
    Vec3f center;
    float radius;
    Vec3f pointFacing(const Vec3f& direction, const Vec2f& u) const;
    float pdf() const { return 1.0f / (kPi<float> * radius * radius); }
};

/// What every light at infinity shares: no surface carries it, and its particles start on
/// the scene's disk.
class InfiniteLight : public Light {
  public:
    float pdf(const Vec3f&, const SurfaceHit&) const final { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const final { return {}; }
    bool isInfinite() const final { return true; }

  protected:
    explicit InfiniteLight(const Geometry& g) : disk_{g.boundsCenter(), g.boundsRadius()} {}

    SceneDisk disk_;
};

/// Parallel light of a given irradiance travelling along one direction.
class DirectionalLight final : public InfiniteLight {
  public:
    DirectionalLight(const DirectionalLightDesc& d, const Geometry& g);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    double power() const override;
    bool isDelta() const override { return true; }

    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const override;

  private:
    Vec3f direction_;
    EmitterColor color_;
};

/// Radiance arriving from every direction: next-event samples and particles are drawn from
/// sampleDirection() and weighted by radianceTowards().
class EnvironmentLight : public InfiniteLight {
  public:
    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const final;
    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const final;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const final;
    /// The environment's radiance along w, wherever it is seen from.
    virtual Emission radianceTowards(const Vec3f& w) const = 0;
    virtual float directionPdf(const Vec3f& w) const = 0;
    Emission environment(const Vec3f&, const Vec3f& w) const final { return radianceTowards(w); }
    float environmentPdf(const Vec3f&, const Vec3f& w) const final { return directionPdf(w); }
    /// Pixels of its image around the horizon, 0 without an image: how fine a grid that steers
    /// samples towards its bright parts needs to be (portal_environment.h).
    virtual int pixelsAroundTheHorizon() const { return 0; }

  protected:
    using InfiniteLight::InfiniteLight;

    /// A direction w (away from the scene) drawn with density directionPdf(w), returned
    /// in `pdf` (0: nothing drawn).
    virtual Vec3f sampleDirection(const Vec2f& u, float& pdf) const = 0;
    /// The flux through the scene's disk from all directions per unit radiance, 4 pi^2 r^2
    /// (pbrt-v4's measure of an environment's power).
    double fluxPerRadiance() const;
};

/// A constant environment: radiance L from every direction, sampled uniformly on the sphere.
class ConstantEnvironment final : public EnvironmentLight {
  public:
    ConstantEnvironment(const EnvironmentLightDesc& d, const Geometry& g);

    double power() const override;
    Emission radianceTowards(const Vec3f&) const override { return {&color_, 1.0f}; }
    float directionPdf(const Vec3f&) const override;

  private:
    Vec3f sampleDirection(const Vec2f& u, float& pdf) const override;

    EmitterColor color_;
};

/// An image around the scene (environment_map.h), importance-sampled.
class ImageEnvironment final : public EnvironmentLight {
  public:
    ImageEnvironment(const EnvironmentLightDesc& d, const Geometry& g);

    double power() const override;
    Emission radianceTowards(const Vec3f& w) const override;
    float directionPdf(const Vec3f& w) const override { return map_.pdf(w); }
    int pixelsAroundTheHorizon() const override { return map_.pixelsAroundTheHorizon(); }

  private:
    Vec3f sampleDirection(const Vec2f& u, float& pdf) const override;

    EnvironmentMap map_;
    float scale_;
};

}  // namespace lamina::render
