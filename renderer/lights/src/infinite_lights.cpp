#include "lamina/lights/infinite_lights.h"

#include "lamina/core/warp.h"

namespace lamina::render {

Vec3f SceneDisk::pointFacing(const Vec3f& direction, const Vec2f& u) const {
    const Vec2f d = squareToUniformDiskConcentric(u) * radius;
    return center - radius * direction +
           Frame<float>::fromNormal(direction).toWorld(Vec3f(d.x, d.y, 0.0f));
}

DirectionalLight::DirectionalLight(const DirectionalLightDesc& d, const Geometry& g)
    : InfiniteLight(g), direction_(Vec3f(d.direction)), color_(d.intensity, d.spectrum) {}

std::optional<LightSample> DirectionalLight::sample(const Vec3f&, const Vec2f&) const {
    return LightSample{-direction_,
                       std::numeric_limits<float>::infinity(),
                       {&color_, 1.0f},
                       1.0f,
                       true,
                       Vec3f(0.0f),
                       direction_};
}

double DirectionalLight::power() const {
    return kPi<double> * sqr(double(disk_.radius)) * luminance(color_.rgbDouble());
}

std::optional<EmissionSample> DirectionalLight::sampleEmission(const Vec2f& u, const Vec2f&) const {
    EmissionSample e;
    e.point = disk_.pointFacing(direction_, u);
    e.direction = e.normal = direction_;
    e.radiance = {&color_, 1.0f};
    e.pdfPosition = disk_.pdf();
    e.deltaDirection = true;
    return e;
}

EmissionPdf DirectionalLight::emissionPdf(const Vec3f&, const Vec3f&, const Vec3f&) const {
    return {disk_.pdf(), 1.0f};
}

std::optional<LightSample> EnvironmentLight::sample(const Vec3f&, const Vec2f& u) const {
    float pdf;
    const Vec3f wi = sampleDirection(u, pdf);
    if (!(pdf > 0.0f)) return std::nullopt;
    return LightSample{
        wi, std::numeric_limits<float>::infinity(), radianceTowards(wi), pdf, false, Vec3f(0.0f),
        -wi};
}

// A direction w the light arrives from, and a start on the disk facing it: the particle
// travels along -w.
std::optional<EmissionSample> EnvironmentLight::sampleEmission(const Vec2f& uPosition,
                                                               const Vec2f& uDirection) const {
    float pdf;
    const Vec3f w = sampleDirection(uDirection, pdf);
    if (!(pdf > 0.0f)) return std::nullopt;
    EmissionSample e;
    e.point = disk_.pointFacing(-w, uPosition);
    e.direction = e.normal = -w;
    e.radiance = radianceTowards(w);
    e.pdfPosition = disk_.pdf();
    e.pdfDirection = pdf;
    return e;
}

EmissionPdf EnvironmentLight::emissionPdf(const Vec3f&, const Vec3f&,
                                          const Vec3f& direction) const {
    return {disk_.pdf(), directionPdf(-direction)};
}

double EnvironmentLight::fluxPerRadiance() const {
    return 4.0 * kPi<double> * kPi<double> * sqr(double(disk_.radius));
}

ConstantEnvironment::ConstantEnvironment(const EnvironmentLightDesc& d, const Geometry& g)
    : EnvironmentLight(g), color_(d.intensity, d.spectrum) {}

double ConstantEnvironment::power() const {
    return fluxPerRadiance() * luminance(color_.rgbDouble());
}

float ConstantEnvironment::directionPdf(const Vec3f&) const {
    return uniformSpherePdf<float>();
}

Vec3f ConstantEnvironment::sampleDirection(const Vec2f& u, float& pdf) const {
    pdf = uniformSpherePdf<float>();
    return squareToUniformSphere(u);
}

ImageEnvironment::ImageEnvironment(const EnvironmentLightDesc& d, const Geometry& g)
    : EnvironmentLight(g),
      map_(d.file, {d.mapping, d.rotation, d.orientation}),
      scale_(float(d.intensity[0])) {}

double ImageEnvironment::power() const {
    return fluxPerRadiance() * scale_ * map_.averageLuminance();
}

Emission ImageEnvironment::radianceTowards(const Vec3f& w) const {
    return Emission{nullptr, scale_, map_.lookup(w)};
}

Vec3f ImageEnvironment::sampleDirection(const Vec2f& u, float& pdf) const {
    return map_.sample(u, pdf);
}

}  // namespace lamina::render
