#include "lamina/integrators/light_integrator.h"

#include "lamina/integrators/particle_start.h"
#include "lamina/integrators/scatter.h"
#include "lamina/integrators/splat.h"

namespace lamina::render {

template <SpectrumType S>
LightIntegrator<S>::LightIntegrator(const IntegratorSetup<S>& setup)
    : c_(setup.context),
      mode_(setup.mode),
      settings_(setup.settings),
      filter_(setup.filter),
      ablations_(setup.ablations) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> LightIntegrator<S>::sample(const PixelSample<S>& ps) const {
    traceParticle(ps.sampler, ps.path, ps.film, ps.stats);
    return std::nullopt;
}

template <SpectrumType S>
void LightIntegrator<S>::traceParticle(PixelSampler& sampler, typename Mode::Path& path, Film& film,
                                       PathStatistics& stats) const {
    const auto particle = startParticle(c_.lights, c_.geometry, mode_, sampler, path);
    if (!particle) return;
    const EmissionSample& e = particle->emission;
    const Light& light = c_.lights.light(particle->light);

    // The emitter itself seen by the camera (no scattering).
    const Vec2f uLens = sampler.get2DIfUsed(!c_.camera.isPinhole());
    if (particle->onSurface) {
        if (const auto cc = c_.camera.sampleConnection(e.point, uLens)) {
            SurfaceHit at;
            at.p = e.point;
            at.ng = at.ns = facing(e.normal, e.normal);
            const Emission toCamera = light.radiance(at, cc->wi);
            if (!toCamera.isZero() && segmentUnoccluded(c_.geometry, e.point, e.normal,
                                                        cc->lensPoint, Vec3f(0.0f), stats)) {
                const float cosLight = std::abs(glm::dot(e.normal, cc->wi));
                const S value =
                    mode_.emission(toCamera, path) *
                    (cosLight * cc->importance / (cc->pdf * particle->pmf * e.pdfPosition));
                splatContribution(film, filter_, cc->raster, mode_, value, cc->wi,
                                  c_.camera.imageRight(), path);
            }
        }
    }

    S beta = particle->beta;
    const float beta0 = beta.maxValue();
    if (!(beta0 > 0.0f) || !beta.isFinite()) return;
    Vec3f o = particle->origin, d = e.direction;
    const TransportMode mode = ablations_.lightPathMode();
    for (int bounces = 1; bounces <= settings_.maxDepth; ++bounces) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if (!hit) break;
        const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
        const ShadingPoint at(hit->p, hit->ng, hit->ns, -d,
                              c_.geometry.rayOffsetScale());  // wo towards the light's side
        const Bxdf<S>& bsdf = mode_.bsdf(shape.material, hit->uv, at.frame, path);

        // Connection to the camera.
        const Vec2f uCamera = sampler.get2DIfUsed(!c_.camera.isPinhole());
        if ((bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0) {
            if (const auto cc = c_.camera.sampleConnection(hit->p, uCamera);
                cc && sidesAgree(at.woWorld, cc->wi, hit->ng, hit->ns)) {
                const Vec3f toCamera = at.frame.toLocal(cc->wi);
                const S f = ablations_.connectionBsdf(bsdf, at.wo, toCamera) *
                            ablations_.adjointCorrection(at.woWorld, cc->wi, hit->ng, hit->ns);
                if (f.maxValue() > 0.0f && segmentUnoccluded(c_.geometry, hit->p, hit->ng,
                                                             cc->lensPoint, Vec3f(0.0f), stats)) {
                    // f before beta: in the polarised mode the light path's matrices act
                    // in the order light meets them (docs/polarisation.md, "Light paths").
                    const S value = f * beta * (cc->importance / cc->pdf);
                    splatContribution(film, filter_, cc->raster, mode_, value, cc->wi,
                                      c_.camera.imageRight(), path);
                }
            }
        }
        if (bounces == settings_.maxDepth) break;

        // Russian roulette on the throughput relative to the particle's start.
        const auto step = scatter(
            bsdf, at, mode, bounces, settings_.russianRouletteDepth, sampler, beta,
            [&](S& b, const BsdfSample<S>& s, const Vec3f& wi) {
                b = s.weight * ablations_.adjointCorrection(at.woWorld, wi, hit->ng, hit->ns) * b;
                return b.maxValue() / beta0;
            });
        if (!step.next) break;
        o = step.next->origin;
        d = step.next->direction;
    }
}

template class LightIntegrator<Rgb<float>>;
template class LightIntegrator<SampledSpectrum<float>>;
template class LightIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
