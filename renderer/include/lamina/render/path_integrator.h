// The `path` integrator: camera path tracing with next-event estimation and BSDF sampling
// combined by multiple importance sampling (Veach 1997, ch. 9, power heuristic), emission
// hit by BSDF sampling weighted the same way, Russian roulette on throughput, delta lobes and
// delta lights handled. The same code runs in every render mode.
#pragma once

#include "lamina/render/integrator_common.h"

namespace lamina::render {

template <SpectrumType S>
class PathIntegrator {
  public:
    using Mode = RenderMode<S>;

    PathIntegrator(const SceneContext& context, const Mode& mode, const RenderSettings& settings)
        : c_(context), mode_(mode), settings_(settings) {}

    /// Radiance along a camera ray. `aovs` (optional) receives first-hit data.
    S radiance(const Vec3f& rayOrigin, const Vec3f& rayDirection, PixelSampler& sampler,
               typename Mode::Path& path, PathStatistics& stats, PixelAovs* aovs) const {
        S L(0.0f), beta(1.0f);
        float etaScale = 1.0f;
        bool specularBounce = true;
        float prevPdf = 0.0f;
        Vec3f prevPoint(0.0f);
        Vec3f o = rayOrigin, d = rayDirection;
        for (int depth = 0;; ++depth) {
            ++stats.rays;
            const auto hit = c_.geometry.intersect(o, d);
            if (!hit) {
                for (std::size_t i : c_.lights.infiniteLights()) {
                    const Light& light = c_.lights.light(i);
                    const Emission Le = light.environment(-d);
                    if (Le.isZero()) continue;
                    const float w = specularBounce
                                        ? 1.0f
                                        : powerHeuristic(prevPdf, c_.lights.probability(i) *
                                                                      light.environmentPdf(-d));
                    L += beta * mode_.emission(Le, path) * w;
                }
                break;
            }
            if (const int li = c_.lights.lightAt(*hit); li >= 0) {
                const Light& light = c_.lights.light(std::size_t(li));
                const Emission Le = light.radiance(*hit, -d);
                if (!Le.isZero()) {
                    const float w =
                        specularBounce
                            ? 1.0f
                            : powerHeuristic(prevPdf, c_.lights.probability(std::size_t(li)) *
                                                          light.pdf(prevPoint, *hit));
                    L += beta * mode_.emission(Le, path) * w;
                }
            }
            if (depth >= settings_.maxDepth) break;

            const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
            const Bxdf<S>& bsdf = mode_.bsdf(shape.material, hit->uv, path);
            const Frame<float> frame = Frame<float>::fromNormal(hit->ns);
            const Vec3f wo = frame.toLocal(-d);

            // Next-event estimation (always draws its three numbers, so the sampler's
            // dimensions mean the same thing at every vertex).
            const float uLight = sampler.get1D();
            const Vec2f uLightPoint = sampler.get2D();
            const bool smooth = (bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0;
            if (smooth && !c_.lights.empty())
                L += beta * directLight(*hit, frame, wo, bsdf, uLight, uLightPoint, path, stats);

            const float uc = sampler.get1D();
            const Vec2f u = sampler.get2D();
            const auto s = bsdf.sample(wo, uc, u, TransportMode::Radiance);
            if (aovs && depth == 0) {
                aovs->normal = Vec3<double>(hit->ns);
                aovs->depth = hit->t;
                if (s) aovs->albedo = mode_.filmValue(s->weight, path);
            }
            if (!s || !(s->pdf > 0.0f)) break;
            const Vec3f wi = frame.toWorld(s->wi);
            // A direction on the wrong side of the geometric surface for its lobe (possible
            // with shading normals) would leak light through the surface.
            if (!sidesAgree(-d, wi, hit->ng, hit->ns)) break;
            beta *= s->weight;
            if (s->isTransmission()) etaScale *= sqr(s->eta);
            specularBounce = s->isSpecular();
            prevPdf = s->pdf;
            prevPoint = hit->p;

            // Russian roulette on the throughput without the radiance eta^2 factors (pbrt-v4).
            const float uRoulette = sampler.get1D();
            if (!russianRoulette(beta, beta.maxValue() * etaScale, depth + 1,
                                 settings_.russianRouletteDepth, uRoulette))
                break;
            if (!beta.isFinite() || beta.maxValue() <= 0.0f) break;
            o = offsetRayOrigin(hit->p, facing(hit->ng, wi));
            d = wi;
        }
        return L;
    }

  private:
    S directLight(const SurfaceHit& hit, const Frame<float>& frame, const Vec3f& wo,
                  const Bxdf<S>& bsdf, float uLight, const Vec2f& uPoint, typename Mode::Path& path,
                  PathStatistics& stats) const {
        const auto [index, pmf] = c_.lights.choose(uLight);
        const Light& light = c_.lights.light(index);
        const auto ls = light.sample(hit.p, uPoint);
        if (!ls || !(ls->pdf > 0.0f) || ls->radiance.isZero()) return S(0.0f);
        if (!sidesAgree(frame.toWorld(wo), ls->wi, hit.ng, hit.ns)) return S(0.0f);
        const Vec3f wi = frame.toLocal(ls->wi);
        const S f = bsdf.eval(wo, wi, TransportMode::Radiance);
        if (f.maxValue() <= 0.0f) return S(0.0f);
        const bool visible =
            std::isinf(ls->distance)
                ? directionUnoccluded(c_.geometry, hit.p, hit.ng, ls->wi, stats)
                : segmentUnoccluded(c_.geometry, hit.p, hit.ng, ls->point, ls->normal, stats);
        if (!visible) return S(0.0f);
        const float lightPdf = pmf * ls->pdf;
        const float w = ls->delta ? 1.0f : powerHeuristic(lightPdf, bsdf.pdf(wo, wi));
        return f * mode_.emission(ls->radiance, path) * (w / lightPdf);
    }

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
};

}  // namespace lamina::render
