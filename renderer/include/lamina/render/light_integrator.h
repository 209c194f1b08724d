// The `light` integrator: light tracing (particle tracing). Particles leave the lights with
// their emission densities, scatter with the BSDFs evaluated and sampled in importance mode
// (the adjoint BSDF: the direction light flows, no 1/eta^2 on refraction) with the adjoint
// shading-normal correction, and every vertex is connected to the camera and splatted on the
// film (Veach 1997, sections 10.2 and 10.8). Delta lobes cannot be connected; delta lights are
// sampled like the others. Infinite lights seen directly cannot be reached by a particle (the
// lens has no area facing infinity); they are missing from this integrator's images.
#pragma once

#include "lamina/render/integrator_common.h"
#include "lamina/render/pixel_filter.h"
#include "lamina/render/splat.h"

namespace lamina::render {

template <SpectrumType S>
class LightIntegrator {
  public:
    using Mode = RenderMode<S>;

    LightIntegrator(const SceneContext& context, const Mode& mode, const RenderSettings& settings,
                    const PixelFilter& filter, const TransportAblations& ablations)
        : c_(context), mode_(mode), settings_(settings), filter_(filter), ablations_(ablations) {}

    /// Traces one particle and splats its contributions (to be scaled by 1 / particles).
    void traceParticle(PixelSampler& sampler, typename Mode::Path& path, Film& film,
                       PathStatistics& stats) const {
        if (c_.lights.empty()) return;
        const float uLight = sampler.get1D();
        const Vec2f uPosition = sampler.get2D(), uDirection = sampler.get2D();
        const auto [index, pmf] = c_.lights.choose(uLight);
        const Light& light = c_.lights.light(index);
        const auto e = light.sampleEmission(uPosition, uDirection);
        if (!e || !(e->pdfPosition > 0.0f) || !(e->pdfDirection > 0.0f) || e->radiance.isZero())
            return;
        const S Le = mode_.emission(e->radiance, path);
        const bool onSurface = !e->deltaPosition && !light.isInfinite();

        // The emitter itself seen by the camera (no scattering).
        const Vec2f uLens = sampler.get2D();
        if (onSurface) {
            if (const auto cc = c_.camera.sampleConnection(e->point, uLens)) {
                SurfaceHit at;
                at.p = e->point;
                at.ng = at.ns = facing(e->normal, e->normal);
                const Emission toCamera = light.radiance(at, cc->wi);
                if (!toCamera.isZero() && segmentUnoccluded(c_.geometry, e->point, e->normal,
                                                            cc->lensPoint, Vec3f(0.0f), stats)) {
                    const float cosLight = std::abs(glm::dot(e->normal, cc->wi));
                    const S value = mode_.emission(toCamera, path) *
                                    (cosLight * cc->importance / (cc->pdf * pmf * e->pdfPosition));
                    splatFiltered(film, filter_, cc->raster, mode_.filmValue(value, path));
                }
            }
        }

        const float cosEmit = std::abs(glm::dot(e->normal, e->direction));
        S beta = Le * (cosEmit / (pmf * e->pdfPosition * e->pdfDirection));
        const float beta0 = beta.maxValue();
        if (!(beta0 > 0.0f) || !beta.isFinite()) return;
        Vec3f o = onSurface ? offsetRayOrigin(e->point, facing(e->normal, e->direction)) : e->point;
        Vec3f d = e->direction;
        const TransportMode mode =
            ablations_.radianceOnLightPaths ? TransportMode::Radiance : TransportMode::Importance;
        for (int bounces = 1; bounces <= settings_.maxDepth; ++bounces) {
            ++stats.rays;
            const auto hit = c_.geometry.intersect(o, d);
            if (!hit) break;
            const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
            const Bxdf<S>& bsdf = mode_.bsdf(shape.material, hit->uv, path);
            const Frame<float> frame = Frame<float>::fromNormal(hit->ns);
            const Vec3f woWorld = -d;  // towards the light's side
            const Vec3f wo = frame.toLocal(woWorld);

            // Connection to the camera.
            const Vec2f uCamera = sampler.get2D();
            if ((bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0) {
                if (const auto cc = c_.camera.sampleConnection(hit->p, uCamera);
                    cc && sidesAgree(woWorld, cc->wi, hit->ng, hit->ns)) {
                    const Vec3f toCamera = frame.toLocal(cc->wi);
                    const S f = (ablations_.swappedConnections ? bsdf.eval(toCamera, wo, mode)
                                                               : bsdf.eval(wo, toCamera, mode)) *
                                correction(woWorld, cc->wi, *hit);
                    if (f.maxValue() > 0.0f &&
                        segmentUnoccluded(c_.geometry, hit->p, hit->ng, cc->lensPoint, Vec3f(0.0f),
                                          stats)) {
                        const S value = beta * f * (cc->importance / cc->pdf);
                        splatFiltered(film, filter_, cc->raster, mode_.filmValue(value, path));
                    }
                }
            }
            if (bounces == settings_.maxDepth) break;

            const float uc = sampler.get1D();
            const Vec2f u = sampler.get2D();
            const auto s = bsdf.sample(wo, uc, u, mode);
            if (!s || !(s->pdf > 0.0f)) break;
            const Vec3f wi = frame.toWorld(s->wi);
            if (!sidesAgree(woWorld, wi, hit->ng, hit->ns)) break;
            beta *= s->weight * correction(woWorld, wi, *hit);

            // Russian roulette on the throughput relative to the particle's start.
            const float uRoulette = sampler.get1D();
            if (!russianRoulette(beta, beta.maxValue() / beta0, bounces,
                                 settings_.russianRouletteDepth, uRoulette))
                break;
            if (!beta.isFinite() || beta.maxValue() <= 0.0f) break;
            o = offsetRayOrigin(hit->p, facing(hit->ng, wi));
            d = wi;
        }
    }

  private:
    float correction(const Vec3f& wo, const Vec3f& wi, const SurfaceHit& hit) const {
        if (ablations_.noAdjointCorrection) return 1.0f;
        return adjointShadingCorrection(wo, wi, hit.ng, hit.ns);
    }

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    TransportAblations ablations_;
};

}  // namespace lamina::render
