// Lights at a point: a point light (intensity I in every direction) and a spot light (I in a
// cone). Both are delta lights: sample() returns the one direction with pdf 1, and the
// surfaces cannot hit them.
#pragma once

#include "lamina/lights/lights.h"

namespace lamina::render {

/// What a light at a point answers the same way whatever its distribution: no surface can
/// hit it (density 0, no radiance), and it is a delta light.
class DeltaPositionLight : public Light {
  public:
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    bool isDelta() const override { return true; }
};

class PointLight final : public DeltaPositionLight {
  public:
    explicit PointLight(const PointLightDesc& d);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    double power() const override;
    /// A point, every direction (theta_o = pi), intensity I.
    std::optional<LightBounds> bounds() const override;

    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const override;

  private:
    Vec3f position_;
    EmitterColor color_;
};

/// A spot light (pbrt-v4's convention): intensity I inside a cone, with a smoothstep falloff
/// in cos(theta) between the falloff start and the cone's edge.
class SpotLight final : public DeltaPositionLight {
  public:
    explicit SpotLight(const SpotLightDesc& d);

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override;
    double power() const override;
    /// A point, the axis with theta_o the falloff start and theta_e the rest of the cone
    /// (pbrt-v4's SpotLight::Bounds), intensity I.
    std::optional<LightBounds> bounds() const override;

    /// Directions uniform in the cone (the falloff is in the weight).
    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override;
    EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                            const Vec3f& direction) const override;

  private:
    float falloff(float cosTheta) const;

    Vec3f position_, axis_;
    EmitterColor color_;
    float cosEdge_, cosStart_;
};

}  // namespace lamina::render
