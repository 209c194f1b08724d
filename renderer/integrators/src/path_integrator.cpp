#include "lamina/integrators/path_integrator.h"

#include <limits>

#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/integrators/medium_transport.h"

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
      aovs_(setup.aovs),
      ablations_(setup.ablations),
      media_(Mode::kRendersMedia && setup.context.scene.hasMedia()) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> PathIntegrator<S>::sample(const PixelSample<S>& ps) const {
    const CameraSample cs = sampleCamera(filter_, c_.camera, ps.sampler, ps.x, ps.y);
    const auto ray = c_.camera.generateRay(cs.raster.x, cs.raster.y, cs.lens);
    CameraEstimate<S> estimate{S(0.0f), cs.filterWeight, std::nullopt, ray.direction};
    if (aovs_) estimate.aovs.emplace();
    // A realistic camera's lens blocks some rays and weights the others (realistic_camera.h).
    if (ray.weight == 0.0f) return estimate;
    estimate.value = radiance(ray.origin, ray.direction, ps.sampler, ps.path, ps.stats,
                              estimate.aovs ? &*estimate.aovs : nullptr);
    if (ray.weight != 1.0f) estimate.value = estimate.value * ray.weight;
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
    // With media (medium_transport.h): the medium the path is in, its hero channel, and the
    // densities of the path per channel relative to the hero's, unidirectional (rU) and, for
    // an emitter the path hits, by light sampling at the last vertex (rL, times the light's
    // density there).
    int medium = -1, hero = 0, crossings = 0;
    S rU(1.0f), rL(1.0f);
    if constexpr (Mode::kRendersMedia) {
        if (media_) {
            medium = c_.scene.camera.medium;
            hero = heroChannel<S>(sampler.get1D());
        }
    }
    // Emission Le reached by the path, weighted against light sampling (lightPdf: the density
    // of the light sample that would have found it).
    const auto reached = [&](const S& Le, float lightPdf) -> S {
        if constexpr (Mode::kRendersMedia) {
            if (media_) {
                if (specularBounce || !nextEvent)
                    return beta * Le / ablations_.channelDensity(rU, hero);
                return beta * Le / ablations_.channelDensity(rU + rL * lightPdf, hero);
            }
        }
        const float w = specularBounce || !nextEvent ? 1.0f : powerHeuristic(prevPdf, lightPdf);
        return beta * Le * w;
    };
    Vec3f o = rayOrigin, d = rayDirection;
    for (int depth = 0;;) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if constexpr (Mode::kRendersMedia) {
            const auto mf =
                media_ ? sampleMediumFlight(mode_, path, medium, hero, sampler, hit) : std::nullopt;
            // The flight passes, ends, or scatters at a medium vertex (medium_transport.h:
            // exact in a homogeneous medium, delta tracking with its null collisions' factors
            // and the emission at its collisions in a grid).
            std::optional<float> scatterAt;
            if (mf) {
                const FlightOutcome f = mf->apply(
                    o, d, hero, beta, rU, &rL, mf->coefficients.emits ? &L : nullptr, ablations_);
                if (f.outcome == FlightOutcome::Outcome::Ends) break;
                if (f.outcome == FlightOutcome::Outcome::Scatters) scatterAt = f.t;
            }
            if (scatterAt) {
                const float g = mf->coefficients.g;
                if (depth >= settings_.maxDepth || !(beta.maxValue() > 0.0f)) break;
                const Vec3f p = o + d * *scatterAt;
                const auto phase = [&](const Vec3f& wi) {
                    return henyeyGreenstein(glm::dot(d, wi), g);
                };
                // The same dimensions as at a surface: the light's two, the lobe choice
                // (none here), the direction's two, the roulette's.
                if (nextEvent && c_.lights.nextEventChooses()) {
                    const float uLight = sampler.get1DIfUsed(c_.lights.choiceReadsNumber());
                    const Vec2f uLightPoint = sampler.get2D();
                    L += beta * directLight(
                                    {p, Vec3f(0.0f), Vec3f(0.0f), nullptr, medium, d, hero},
                                    [&](const Vec3f& wi) { return S(phase(wi)); }, phase, rU,
                                    uLight, uLightPoint, path, stats);
                } else {
                    sampler.skip();
                    sampler.skip();
                }
                sampler.skip();
                const Vec3f wi = sampleHenyeyGreenstein(d, g, sampler.get2D());
                // The phase function is its own density: the throughput keeps sigma_s.
                prevPdf = phase(wi);
                rL = rU / prevPdf;
                const float rrBeta = (beta / rU.average()).maxValue() * etaScale;
                if (rouletteApplies(rrBeta, depth + 1, settings_.russianRouletteDepth)) {
                    if (!russianRoulette(beta, rrBeta, depth + 1, settings_.russianRouletteDepth,
                                         sampler.get1D()))
                        break;
                } else {
                    sampler.skip();
                }
                if (!beta.isFinite()) break;
                specularBounce = false;
                crossings = 0;
                prevPoint = p;
                prevNormal = Vec3f(0.0f);
                o = p;
                d = wi;
                ++depth;
                continue;
            }
        }
        if (!hit) {
            for (std::size_t i : c_.lights.infiniteLights()) {
                const Light& light = c_.lights.light(i);
                const Emission Le = light.environment(o, d);
                if (Le.isZero()) continue;
                const float lightPdf = specularBounce || !nextEvent
                                           ? 0.0f
                                           : c_.lights.probability(i, prevPoint, prevNormal) *
                                                 light.environmentPdf(o, d);
                L += reached(mode_.emission(Le, path), lightPdf);
            }
            break;
        }
        if (const int li = c_.lights.lightAt(*hit); li >= 0) {
            const Light& light = c_.lights.light(std::size_t(li));
            const Emission Le = light.radiance(*hit, -d);
            if (!Le.isZero()) {
                const float lightPdf =
                    specularBounce || !nextEvent
                        ? 0.0f
                        : c_.lights.probability(std::size_t(li), prevPoint, prevNormal) *
                              light.pdf(prevPoint, *hit);
                L += reached(mode_.emission(Le, path), lightPdf);
            }
        }

        const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
        if (media_ && surface(*shape.desc).isInterface()) {
            // An index-matched boundary: the path goes straight on into the other medium; no
            // scattering event, so the depth and the MIS state stay as they were.
            if (++crossings > kMaxInterfaceCrossings) break;
            medium = mediumAfter(shape, medium, hit->ng, d, d);
            o = offsetRayOrigin(hit->p, facing(hit->ng, d), c_.geometry.rayOffsetScale());
            continue;
        }
        if (depth >= settings_.maxDepth) break;

        const ShadingPoint at(hit->p, hit->ng, hit->ns, -d, c_.geometry.rayOffsetScale(),
                              hit->tangent);
        const Bxdf<S>& bsdf =
            mode_.bsdf(shape.material, {hit->uv, hit->p, hit->ng}, at.frame, path);

        // Next-event estimation (its two dimensions are used at every vertex, skipped when
        // there is no estimate to make or, the light's, no light to choose between, so the
        // sampler's dimensions mean the same thing at every vertex).
        const bool smooth = (bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0;
        if (nextEvent && smooth && c_.lights.nextEventChooses()) {
            const float uLight = sampler.get1DIfUsed(c_.lights.choiceReadsNumber());
            const Vec2f uLightPoint = sampler.get2D();
            const auto f = [&](const Vec3f& wi) {
                // A direction on the wrong side of the geometric surface for its lobe would
                // leak light through it (shading_normals.h).
                if (!sidesAgree(at.frame.toWorld(at.wo), wi, hit->ng, hit->ns)) return S(0.0f);
                return bsdf.eval(at.wo, at.frame.toLocal(wi), TransportMode::Radiance);
            };
            const auto pdf = [&](const Vec3f& wi) { return bsdf.pdf(at.wo, at.frame.toLocal(wi)); };
            L += beta * directLight({hit->p, hit->ng, hit->ns, &shape, medium, d, hero}, f, pdf, rU,
                                    uLight, uLightPoint, path, stats);
        } else {
            sampler.skip();
            sampler.skip();
        }

        // Russian roulette on the throughput without the radiance eta^2 factors (pbrt-v4),
        // relative to the path's density (its average over the channels, with media).
        const auto step =
            scatter(bsdf, at, TransportMode::Radiance, depth + 1, settings_.russianRouletteDepth,
                    sampler, beta, [&](S& b, const BsdfSample<S>& s, const Vec3f&) {
                        b *= s.weight;
                        if (s.isTransmission()) etaScale *= sqr(s.eta);
                        if constexpr (Mode::kRendersMedia) {
                            if (media_) return (b / rU.average()).maxValue() * etaScale;
                        }
                        return b.maxValue() * etaScale;
                    });
        if (aovs && depth == 0) {
            aovs->normal = Vec3<double>(hit->ns);
            aovs->depth = hit->t;
            if (step.sample) aovs->albedo = mode_.filmValue(step.sample->weight, path);
        }
        if (!step.next) break;
        if (media_) {
            medium = mediumAfter(shape, medium, hit->ng, d, step.next->direction);
            rL = rU / step.sample->pdf;
            crossings = 0;
        }
        specularBounce = step.sample->isSpecular();
        prevPdf = step.sample->pdf;
        prevPoint = hit->p;
        prevNormal = hit->ns;
        o = step.next->origin;
        d = step.next->direction;
        ++depth;
    }
    return L;
}

template <SpectrumType S>
template <typename Value, typename Density>
S PathIntegrator<S>::directLight(const Vertex& v, Value&& value, Density&& density,
                                 [[maybe_unused]] const S& pathRatios, float uLight,
                                 const Vec2f& uPoint, typename Mode::Path& path,
                                 PathStatistics& stats) const {
    const auto choice = c_.lights.choose(v.p, v.ns, uLight);
    if (!choice) return S(0.0f);
    const float pmf = choice->probability;
    const Light& light = c_.lights.light(choice->index);
    const auto ls = light.sample(v.p, uPoint);
    if (!ls || !(ls->pdf > 0.0f) || ls->radiance.isZero()) return S(0.0f);
    const S f = value(ls->wi);
    if (f.maxValue() <= 0.0f) return S(0.0f);
    const float lightPdf = pmf * ls->pdf;
    if (!media_) {
        const bool visible =
            std::isinf(ls->distance)
                ? directionUnoccluded(c_.geometry, v.p, v.ng, ls->wi, stats)
                : segmentUnoccluded(c_.geometry, v.p, v.ng, ls->point, ls->normal, stats);
        if (!visible) return S(0.0f);
        const float w = ls->delta ? 1.0f : powerHeuristic(lightPdf, density(ls->wi));
        return f * mode_.emission(ls->radiance, path) * (w / lightPdf);
    }
    if constexpr (Mode::kRendersMedia) {
        // The shadow ray leaves in the medium of the side it goes to, through every
        // interface on its way; its end points are moved off their surfaces as
        // segmentUnoccluded moves them (visibility.h).
        const int medium =
            v.shape ? mediumAfter(*v.shape, v.medium, v.ng, v.arrival, ls->wi) : v.medium;
        const float scale = c_.geometry.rayOffsetScale();
        const Vec3f from =
            v.ng == Vec3f(0.0f) ? v.p : offsetRayOrigin(v.p, facing(v.ng, ls->wi), scale);
        Vec3f direction = ls->wi;
        float distance = std::numeric_limits<float>::infinity();
        if (!std::isinf(ls->distance)) {
            const Vec3f to = ls->normal == Vec3f(0.0f)
                                 ? ls->point
                                 : offsetRayOrigin(ls->point, facing(ls->normal, -ls->wi), scale);
            const float length = glm::length(to - from);
            if (!(length > 0.0f)) return S(0.0f);
            direction = (to - from) / length;
            distance = length * (1.0f - 1e-4f);
        }
        const auto T = shadowTransmittance(c_.geometry, mode_, path, from, direction, distance,
                                           medium, v.hero, stats);
        if (!T) return S(0.0f);
        // The balance heuristic over the two strategies and the channels: the light sample's
        // density per channel (times its ratio tracking's in grid media), and the density with
        // which scattering and free flights would have reached the same point (a channel
        // passes the shadow ray's homogeneous media with probability T, a grid's null
        // collisions with T->passing). Relative to the hero's, as pathRatios are.
        const S rLight = pathRatios * lightPdf * T->rL;
        const S denominator =
            ls->delta ? rLight : rLight + pathRatios * density(ls->wi) * T->passing;
        return f * T->T * mode_.emission(ls->radiance, path) /
               ablations_.channelDensity(denominator, v.hero);
    }
    return S(0.0f);
}

template class PathIntegrator<Rgb<float>>;
template class PathIntegrator<SampledSpectrum<float>>;
template class PathIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
