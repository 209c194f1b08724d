#include "lamina/integrators/particle_start.h"

#include "lamina/core/warp.h"
#include "lamina/integrators/medium_transport.h"
#include "lamina/integrators/visibility.h"

namespace lamina::render {

namespace {

/// The particle of light `index`, chosen with probability `pmf`.
template <SpectrumType S>
std::optional<ParticleStart<S>> fromLight(const LightSet& lights, const Geometry& geometry,
                                          const RenderMode<S>& mode,
                                          typename RenderMode<S>::Path& path, std::size_t index,
                                          float pmf, const Vec2f& uPosition,
                                          const Vec2f& uDirection) {
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

}  // namespace

template <SpectrumType S>
std::optional<ParticleStart<S>> startParticle(const LightSet& lights, const Geometry& geometry,
                                              const RenderMode<S>& mode, PixelSampler& sampler,
                                              typename RenderMode<S>::Path& path,
                                              const MediumEmitters& emitters) {
    const bool media = !emitters.empty();
    const float uLight =
        media ? sampler.get1D() : sampler.get1DIfUsed(lights.emitterChoiceReadsNumber());
    const Vec2f uPosition = sampler.get2D(), uDirection = sampler.get2D();
    if (!media) {
        if (lights.empty()) return std::nullopt;
        const auto [index, pmf] = lights.chooseEmitter(uLight);
        return fromLight(lights, geometry, mode, path, index, pmf, uPosition, uDirection);
    }
    const float uVolume = sampler.get1D();
    const MediumEmitters::Choice choice = emitters.choose(uLight);
    if (!(choice.probability > 0.0f)) return std::nullopt;
    if (choice.light >= 0)
        return fromLight(lights, geometry, mode, path, std::size_t(choice.light),
                         choice.probability, uPosition, uDirection);
    if constexpr (RenderMode<S>::kRendersMedia) {
        const auto v =
            emitters.samplePoint(choice.medium, Vec3f(uPosition.x, uPosition.y, uVolume));
        if (!v || !(v->pdf > 0.0f)) return std::nullopt;
        const MediumCoefficients<S> m = mode.medium(choice.medium, path);
        // A point where the medium emits nothing (a grid's cell of partly zero density) is
        // still a particle, a dark one: BDPT's next-event estimation runs for every light
        // subpath that starts.
        const S source = coefficientsAtPoint(m, v->p).sigmaA * m.emission;
        EmissionSample e;
        e.point = v->p;
        e.normal = Vec3f(0.0f);
        e.direction = squareToUniformSphere(uDirection);
        e.pdfPosition = v->pdf;
        e.pdfDirection = uniformSpherePdf<float>();
        const float pdf = choice.probability * e.pdfPosition * e.pdfDirection;
        return ParticleStart<S>{0,    choice.probability, e,     false, source / pdf,
                                v->p, choice.medium,      source};
    }
    return std::nullopt;
}

template std::optional<ParticleStart<Rgb<float>>> startParticle(const LightSet&, const Geometry&,
                                                                const RenderMode<Rgb<float>>&,
                                                                PixelSampler&,
                                                                RenderMode<Rgb<float>>::Path&,
                                                                const MediumEmitters&);
template std::optional<ParticleStart<SampledSpectrum<float>>> startParticle(
    const LightSet&, const Geometry&, const RenderMode<SampledSpectrum<float>>&, PixelSampler&,
    RenderMode<SampledSpectrum<float>>::Path&, const MediumEmitters&);
template std::optional<ParticleStart<PolarisedSpectrum>> startParticle(
    const LightSet&, const Geometry&, const RenderMode<PolarisedSpectrum>&, PixelSampler&,
    RenderMode<PolarisedSpectrum>::Path&, const MediumEmitters&);

}  // namespace lamina::render
