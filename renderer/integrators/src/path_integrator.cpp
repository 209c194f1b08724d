#include "lamina/integrators/path_integrator.h"

namespace lamina::render {

namespace {

/// The power heuristic with beta = 2 (Veach 1997, eq. 9.13) for one sample of each strategy.
float powerHeuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    if (!std::isfinite(a2)) return 1.0f;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

}  // namespace

template <SpectrumType S>
PathIntegrator<S>::PathIntegrator(const IntegratorSetup<S>& setup)
    : c_(setup.context),
      mode_(setup.mode),
      settings_(setup.settings),
      filter_(setup.filter),
      aovs_(setup.aovs) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> PathIntegrator<S>::sample(const PixelSample<S>& ps) const {
    const CameraSample cs = sampleCamera(filter_, c_.camera, ps.sampler, ps.x, ps.y);
    const auto ray = c_.camera.generateRay(cs.raster.x, cs.raster.y, cs.lens);
    CameraEstimate<S> estimate{S(0.0f), cs.filterWeight, std::nullopt, ray.direction};
    if (aovs_) estimate.aovs.emplace();
    estimate.value = radiance(ray.origin, ray.direction, ps.sampler, ps.path, ps.stats,
                              estimate.aovs ? &*estimate.aovs : nullptr);
    return estimate;
}

template <SpectrumType S>
S PathIntegrator<S>::radiance(const Vec3f& rayOrigin, const Vec3f& rayDirection,
                              PixelSampler& sampler, typename Mode::Path& path,
                              PathStatistics& stats, PixelAovs* aovs) const {
    S L(0.0f), beta(1.0f);
    float etaScale = 1.0f;
    // Without next-event estimation BSDF sampling is the only strategy: every emitter it hits
    // counts with full weight, as after a delta bounce.
    const bool nextEvent = settings_.nextEvent;
    bool specularBounce = true;
    float prevPdf = 0.0f;
    Vec3f prevPoint(0.0f), prevNormal(0.0f);  // where the last light was chosen
    Vec3f o = rayOrigin, d = rayDirection;
    for (int depth = 0;; ++depth) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if (!hit) {
            for (std::size_t i : c_.lights.infiniteLights()) {
                const Light& light = c_.lights.light(i);
                const Emission Le = light.environment(-d);
                if (Le.isZero()) continue;
                const float w =
                    specularBounce || !nextEvent
                        ? 1.0f
                        : powerHeuristic(prevPdf, c_.lights.probability(i, prevPoint, prevNormal) *
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
                    specularBounce || !nextEvent
                        ? 1.0f
                        : powerHeuristic(prevPdf, c_.lights.probability(std::size_t(li), prevPoint,
                                                                        prevNormal) *
                                                      light.pdf(prevPoint, *hit));
                L += beta * mode_.emission(Le, path) * w;
            }
        }
        if (depth >= settings_.maxDepth) break;

        const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
        const ShadingPoint at(hit->p, hit->ng, hit->ns, -d, c_.geometry.rayOffsetScale());
        const Bxdf<S>& bsdf = mode_.bsdf(shape.material, hit->uv, at.frame, path);

        // Next-event estimation (its two dimensions are used at every vertex, skipped when
        // there is no estimate to make or, the light's, no light to choose between, so the
        // sampler's dimensions mean the same thing at every vertex).
        const bool smooth = (bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0;
        if (nextEvent && smooth && c_.lights.nextEventChooses()) {
            const float uLight = sampler.get1DIfUsed(c_.lights.choiceReadsNumber());
            const Vec2f uLightPoint = sampler.get2D();
            L += beta * directLight(*hit, at, bsdf, uLight, uLightPoint, path, stats);
        } else {
            sampler.skip();
            sampler.skip();
        }

        // Russian roulette on the throughput without the radiance eta^2 factors (pbrt-v4).
        const auto step =
            scatter(bsdf, at, TransportMode::Radiance, depth + 1, settings_.russianRouletteDepth,
                    sampler, beta, [&](S& b, const BsdfSample<S>& s, const Vec3f&) {
                        b *= s.weight;
                        if (s.isTransmission()) etaScale *= sqr(s.eta);
                        return b.maxValue() * etaScale;
                    });
        if (aovs && depth == 0) {
            aovs->normal = Vec3<double>(hit->ns);
            aovs->depth = hit->t;
            if (step.sample) aovs->albedo = mode_.filmValue(step.sample->weight, path);
        }
        if (!step.next) break;
        specularBounce = step.sample->isSpecular();
        prevPdf = step.sample->pdf;
        prevPoint = hit->p;
        prevNormal = hit->ns;
        o = step.next->origin;
        d = step.next->direction;
    }
    return L;
}

template <SpectrumType S>
S PathIntegrator<S>::directLight(const SurfaceHit& hit, const ShadingPoint& at, const Bxdf<S>& bsdf,
                                 float uLight, const Vec2f& uPoint, typename Mode::Path& path,
                                 PathStatistics& stats) const {
    const auto choice = c_.lights.choose(hit.p, hit.ns, uLight);
    if (!choice) return S(0.0f);
    const float pmf = choice->probability;
    const Light& light = c_.lights.light(choice->index);
    const auto ls = light.sample(hit.p, uPoint);
    if (!ls || !(ls->pdf > 0.0f) || ls->radiance.isZero()) return S(0.0f);
    if (!sidesAgree(at.frame.toWorld(at.wo), ls->wi, hit.ng, hit.ns)) return S(0.0f);
    const Vec3f wi = at.frame.toLocal(ls->wi);
    const S f = bsdf.eval(at.wo, wi, TransportMode::Radiance);
    if (f.maxValue() <= 0.0f) return S(0.0f);
    const bool visible =
        std::isinf(ls->distance)
            ? directionUnoccluded(c_.geometry, hit.p, hit.ng, ls->wi, stats)
            : segmentUnoccluded(c_.geometry, hit.p, hit.ng, ls->point, ls->normal, stats);
    if (!visible) return S(0.0f);
    const float lightPdf = pmf * ls->pdf;
    const float w = ls->delta ? 1.0f : powerHeuristic(lightPdf, bsdf.pdf(at.wo, wi));
    return f * mode_.emission(ls->radiance, path) * (w / lightPdf);
}

template class PathIntegrator<Rgb<float>>;
template class PathIntegrator<SampledSpectrum<float>>;
template class PathIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
