#include "lamina/lights/point_lights.h"

#include "lamina/core/warp.h"

namespace lamina::render {

PointLight::PointLight(const PointLightDesc& d)
    : position_(Vec3f(d.position)), color_(d.intensity, d.spectrum) {}

std::optional<LightSample> PointLight::sample(const Vec3f& ref, const Vec2f&) const {
    const Vec3f d = position_ - ref;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    return LightSample{d / dist, dist, {&color_, 1.0f / dist2}, 1.0f, true, position_, -d / dist};
}

double PointLight::power() const {
    return 4.0 * kPi<double> * luminance(color_.rgbDouble());
}

std::optional<LightBounds> PointLight::bounds() const {
    LightBounds b;
    b.lower = b.upper = position_;
    b.cosThetaO = -1.0f;
    b.cosThetaE = 0.0f;
    b.intensity = float(luminance(color_.rgbDouble()));
    return b;
}

std::optional<EmissionSample> PointLight::sampleEmission(const Vec2f&, const Vec2f& u) const {
    EmissionSample e;
    e.point = position_;
    e.direction = e.normal = squareToUniformSphere(u);
    e.radiance = {&color_, 1.0f};
    e.pdfDirection = uniformSpherePdf<float>();
    e.deltaPosition = true;
    return e;
}

EmissionPdf PointLight::emissionPdf(const Vec3f&, const Vec3f&, const Vec3f&) const {
    return {1.0f, uniformSpherePdf<float>()};
}

SpotLight::SpotLight(const SpotLightDesc& d)
    : position_(Vec3f(d.position)),
      axis_(Vec3f(d.direction)),
      color_(d.intensity, d.spectrum),
      cosEdge_(float(std::cos(radians(d.coneAngle)))),
      cosStart_(float(std::cos(radians(d.falloffStart)))) {}

std::optional<LightSample> SpotLight::sample(const Vec3f& ref, const Vec2f&) const {
    const Vec3f d = position_ - ref;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    const float falloff = this->falloff(glm::dot(-d / dist, axis_));
    if (!(falloff > 0.0f)) return std::nullopt;
    return LightSample{d / dist,  dist,     {&color_, falloff / dist2}, 1.0f, true,
                       position_, -d / dist};
}

double SpotLight::power() const {
    // Integral of the falloff over the sphere: full inside the start, half the smoothstep
    // band on average (pbrt-v4, SpotLight::Phi).
    return 2.0 * kPi<double> * luminance(color_.rgbDouble()) *
           ((1.0 - cosStart_) + (cosStart_ - cosEdge_) / 2.0);
}

std::optional<LightBounds> SpotLight::bounds() const {
    LightBounds b;
    b.lower = b.upper = position_;
    b.axis = axis_;
    b.cosThetaO = cosStart_;
    b.cosThetaE = std::cos(safeAcos(cosEdge_) - safeAcos(cosStart_));
    b.intensity = float(luminance(color_.rgbDouble()));
    return b;
}

std::optional<EmissionSample> SpotLight::sampleEmission(const Vec2f&, const Vec2f& u) const {
    const Vec3f local = squareToUniformCone(u, cosEdge_);
    EmissionSample e;
    e.point = position_;
    e.direction = e.normal = Frame<float>::fromNormal(axis_).toWorld(local);
    const float f = falloff(local.z);
    if (!(f > 0.0f)) return std::nullopt;
    e.radiance = {&color_, f};
    e.pdfDirection = uniformConePdf(local, cosEdge_);
    e.deltaPosition = true;
    return e;
}

EmissionPdf SpotLight::emissionPdf(const Vec3f&, const Vec3f&, const Vec3f& direction) const {
    const float c = glm::dot(direction, axis_);
    return {1.0f, c > cosEdge_ ? uniformConePdf(Vec3f(0, 0, c), cosEdge_) : 0.0f};
}

float SpotLight::falloff(float cosTheta) const {
    if (cosTheta >= cosStart_) return 1.0f;
    if (cosTheta <= cosEdge_) return 0.0f;
    const float t = (cosTheta - cosEdge_) / (cosStart_ - cosEdge_);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace lamina::render
