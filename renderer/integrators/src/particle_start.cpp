#include "lamina/integrators/particle_start.h"

#include "lamina/integrators/visibility.h"

namespace lamina::render {

template <SpectrumType S>
std::optional<ParticleStart<S>> startParticle(const LightSet& lights, const Geometry& geometry,
                                              const RenderMode<S>& mode, PixelSampler& sampler,
                                              typename RenderMode<S>::Path& path) {
    const float uLight = sampler.get1DIfUsed(lights.emitterChoiceReadsNumber());
    const Vec2f uPosition = sampler.get2D(), uDirection = sampler.get2D();
    if (lights.empty()) return std::nullopt;
    const auto [index, pmf] = lights.chooseEmitter(uLight);
    const Light& light = lights.light(index);
    const auto e = light.sampleEmission(uPosition, uDirection);
    if (!e || !(e->pdfPosition > 0.0f) || !(e->pdfDirection > 0.0f) || e->radiance.isZero())
        return std::nullopt;
    const S Le = mode.emission(e->radiance, path);
    const float cosEmit = std::abs(glm::dot(e->normal, e->direction));
    const bool onSurface = !e->deltaPosition && !light.isInfinite();
    return ParticleStart<S>{index,
                            pmf,
                            *e,
                            onSurface,
                            Le * (cosEmit / (pmf * e->pdfPosition * e->pdfDirection)),
                            onSurface ? offsetRayOrigin(e->point, facing(e->normal, e->direction),
                                                        geometry.rayOffsetScale())
                                      : e->point};
}

template std::optional<ParticleStart<Rgb<float>>> startParticle(const LightSet&, const Geometry&,
                                                                const RenderMode<Rgb<float>>&,
                                                                PixelSampler&,
                                                                RenderMode<Rgb<float>>::Path&);
template std::optional<ParticleStart<SampledSpectrum<float>>> startParticle(
    const LightSet&, const Geometry&, const RenderMode<SampledSpectrum<float>>&, PixelSampler&,
    RenderMode<SampledSpectrum<float>>::Path&);
template std::optional<ParticleStart<PolarisedSpectrum>> startParticle(
    const LightSet&, const Geometry&, const RenderMode<PolarisedSpectrum>&, PixelSampler&,
    RenderMode<PolarisedSpectrum>::Path&);

}  // namespace lamina::render
