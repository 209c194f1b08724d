#include "lamina/integrators/bdpt_integrator.h"

#include <limits>

#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/integrators/medium_transport.h"
#include "lamina/integrators/particle_start.h"
#include "lamina/integrators/scatter.h"
#include "lamina/integrators/splat.h"

namespace lamina::render {

template <SpectrumType S>
BdptIntegrator<S>::BdptIntegrator(const IntegratorSetup<S>& setup)
    : c_(setup.context),
      mode_(setup.mode),
      settings_(setup.settings),
      filter_(setup.filter),
      ablations_(setup.ablations),
      strategies_(setup.strategies),
      media_(Mode::kRendersMedia && setup.context.scene.hasMedia()),
      emitters_(setup.context, media_),
      mis_(c_, mode_, setup.settings.mis, emitters_),
      connector_(c_, mode_, ablations_, mis_) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> BdptIntegrator<S>::sample(const PixelSample<S>& ps) const {
    const CameraSample cs = sampleCamera(filter_, c_.camera, ps.sampler, ps.x, ps.y);
    thread_local std::vector<Vertex> cameraPath, lightPath;
    cameraPath.clear();
    lightPath.clear();
    // With media: the hero channel of both subpaths' free flights (medium_transport.h), drawn
    // only then, so that a scene without media draws the numbers it drew before.
    int hero = 0;
    if constexpr (Mode::kRendersMedia) {
        if (media_) hero = heroChannel<S>(ps.sampler.get1D());
    }
    const Vec3f rayDirection =
        generateCameraSubpath(cs, ps.sampler, ps.path, hero, cameraPath, ps.stats);
    generateLightSubpath(ps.sampler, ps.path, hero, lightPath, ps.stats);

    S L(0.0f);
    const int nc = int(cameraPath.size()), nl = int(lightPath.size());
    // A light subpath that starts in an emitting medium's volume: strategy (1, t) joins its
    // first vertex too, beside next-event estimation's fresh light point.
    const bool volumeStart = nl > 0 && lightPath[0].volume;
    const auto add = [&](int s, int t, const BdptConnection<S>& c) {
        if (c.contribution.maxValue() <= 0.0f || !c.contribution.isFinite()) return;
        const S weighted = c.contribution * c.misWeight;
        if (t == 1)
            splatContribution(ps.film, filter_, c.splatAt, mode_, weighted, c.toLens,
                              c_.camera.imageRight(), ps.path);
        else
            L += weighted;
        if (strategies_)
            recordStrategy(s, t, mode_.filmValue(weighted, ps.path),
                           mode_.filmValue(c.contribution, ps.path), c.splatAt, ps.x, ps.y,
                           cs.filterWeight);
    };
    for (int t = 1; t <= nc; ++t) {
        for (int s = 0; s <= nl; ++s) {
            const int depth = s + t - 2;
            // (1, 1) would connect a light point to the lens: the emitter seen directly,
            // which (0, 2) already counts with weight 1 (pbrt-v3 does the same).
            if (depth < 0 || depth > settings_.maxDepth || (s == 1 && t == 1)) continue;
            add(s, t,
                connector_.connect(lightPath, s, cameraPath, t, hero, ps.sampler, ps.path,
                                   ps.stats));
            if (s == 1 && volumeStart)
                add(s, t,
                    connector_.connectVolumeLight(lightPath, cameraPath, t, hero, ps.path,
                                                  ps.stats));
        }
    }
    if (strategies_) strategies_->addWeight(ps.x, ps.y, cs.filterWeight);
    return CameraEstimate<S>{L, cs.filterWeight, std::nullopt, rayDirection};
}

template <SpectrumType S>
void BdptIntegrator<S>::recordStrategy(int s, int t, const Rgb<double>& weighted,
                                       const Rgb<double>& unweighted, const Vec2f& splatAt, int px,
                                       int py, float filterWeight) const {
    const int slot = strategies_->slot(s, t);
    if (slot < 0) return;
    if (!weighted.isFinite() || !unweighted.isFinite() || weighted.hasNegative() ||
        unweighted.hasNegative())
        return;
    if (t == 1)
        strategies_->splatFiltered(slot, filter_, splatAt, weighted, unweighted);
    else
        strategies_->addCamera(slot, px, py, weighted, unweighted, filterWeight);
}

template <SpectrumType S>
Vec3f BdptIntegrator<S>::generateCameraSubpath(const CameraSample& cs, PixelSampler& sampler,
                                               typename Mode::Path& path, int hero,
                                               std::vector<Vertex>& out,
                                               PathStatistics& stats) const {
    const auto ray = c_.camera.generateRay(cs.raster.x, cs.raster.y, cs.lens);
    Vertex v;
    v.type = BdptVertexType::Camera;
    v.p = ray.origin;
    v.beta = S(1.0f);
    v.medium = media_ ? c_.scene.camera.medium : -1;
    out.push_back(v);
    const float pdfDir = c_.camera.rayPdf(ray.direction).direction;
    randomWalk({ray.origin, ray.direction, S(1.0f), pdfDir, v.medium, hero}, settings_.maxDepth + 1,
               TransportMode::Radiance, sampler, path, out, stats);
    // Parallel rays (orthographic): the first vertex's density is the film's, projected.
    if (c_.camera.parallel() && out.size() > 1 && !out[1].infinite)
        out[1].pdfFwd = c_.camera.parallelPdf(out[1].ng, out[1].onSurface());
    return ray.direction;
}

template <SpectrumType S>
void BdptIntegrator<S>::generateLightSubpath(PixelSampler& sampler, typename Mode::Path& path,
                                             int hero, std::vector<Vertex>& out,
                                             PathStatistics& stats) const {
    const auto particle = startParticle(c_.lights, c_.geometry, mode_, sampler, path, emitters_);
    if (!particle) return;
    const EmissionSample& e = particle->emission;
    Vertex v;
    v.type = BdptVertexType::Light;
    if (particle->medium >= 0) {
        // A point of an emitting medium's volume (medium_emitters.h): its emission sigma_a Le,
        // isotropic, over the density of choosing the medium and the point.
        v.volume = true;
        v.medium = particle->medium;
        v.p = e.point;
        v.beta = particle->volumeEmission / (particle->pmf * e.pdfPosition);
    } else {
        const Light& light = c_.lights.light(particle->light);
        v.light = int(particle->light);
        v.infinite = light.isInfinite();
        v.deltaLight = light.isDelta();
        v.p = v.infinite ? -e.direction : e.point;
        v.ng = v.ns = (e.deltaPosition || v.infinite) ? Vec3f(0.0f) : e.normal;
        v.beta = S(1.0f / (particle->pmf * e.pdfPosition));
    }
    v.pdfFwd = mis_.pdfLightOrigin(v);
    out.push_back(v);

    S beta = particle->beta, rU(1.0f);
    int medium = -1;
    if constexpr (Mode::kRendersMedia) {
        if (media_) {
            // The medium of the particle's first ray, as light tracing finds it (docs/media.md):
            // walking from the camera to the ray's origin; light from infinity through a medium
            // that reaches infinity is exp(-sigma_t infinity).
            medium = mediumAt(c_.geometry, c_.scene.camera.medium, Vec3f(c_.scene.camera.position),
                              particle->origin, stats);
            // A point of an emitting medium's box outside the medium carries nothing (one try,
            // so that the density stays the box's). Its vertex stays, dark: next-event
            // estimation (s = 1) runs for every light subpath that has a vertex.
            if (v.volume && medium != v.medium) {
                out.back().beta = S(0.0f);
                return;
            }
            if (v.infinite && medium >= 0)
                fromInfinity(mode_, path, medium, hero, particle->origin, e.direction, beta, rU);
        }
    }
    const std::size_t first = out.size();
    randomWalk({particle->origin, e.direction, beta, e.pdfDirection, medium, hero, rU},
               settings_.maxDepth, TransportMode::Importance, sampler, path, out, stats);
    // From infinity the first vertex's density is per unit perpendicular area, projected on a
    // surface (not 1/d^2): the MIS weights' density of the lights at infinity (bdpt_mis.cpp).
    if (v.infinite && out.size() > first)
        out[first].pdfFwd = mis_.pdfLight(out[first - 1], out[first]);
}

/// Extends a subpath from its last vertex along start's ray until `maxVertices` vertices
/// (surface or medium) are added. Index-matched interfaces are crossed, not vertices.
template <SpectrumType S>
void BdptIntegrator<S>::randomWalk(WalkStart start, int maxVertices, TransportMode mode,
                                   PixelSampler& sampler, typename Mode::Path& path,
                                   std::vector<Vertex>& out, PathStatistics& stats) const {
    Vec3f o = start.o, d = start.d;
    S beta = start.beta;
    float pdfDir = start.pdfDir;
    int medium = start.medium;
    const float beta0 = beta.maxValue();
    if (!(beta0 > 0.0f)) return;
    const bool lightPath = mode == TransportMode::Importance;
    const TransportMode bsdfMode = lightPath ? ablations_.lightPathMode() : mode;
    // With media: the subpath's densities per channel relative to the hero's
    // (medium_transport.h); Russian roulette compares the throughput over their average.
    S rU = start.rU;
    int crossings = 0;
    for (int vertices = 0; vertices < maxVertices;) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if constexpr (Mode::kRendersMedia) {
            const auto mf = media_
                                ? sampleMediumFlight(mode_, path, medium, start.hero, sampler, hit)
                                : std::nullopt;
            // The flight passes, ends, or scatters at a medium vertex (medium_transport.h); a
            // camera subpath's vertex in an emitting medium keeps the emission there (s = 0).
            std::optional<float> scatterAt;
            S emission(0.0f);
            if (mf) {
                const bool emits = !lightPath && mf->coefficients.emits && !emitters_.empty();
                const FlightOutcome f = mf->apply(o, d, start.hero, beta, rU, nullptr, nullptr,
                                                  ablations_, emits ? &emission : nullptr);
                if (f.outcome == FlightOutcome::Outcome::Ends) return;
                if (f.outcome == FlightOutcome::Outcome::Scatters) scatterAt = f.t;
            }
            if (scatterAt) {
                // A vertex that scatters nothing (sigma_s = 0) still ends a path that emits.
                const bool scatters = beta.maxValue() > 0.0f;
                if (!scatters && !(emission.maxValue() > 0.0f)) return;
                Vertex v;
                v.type = BdptVertexType::Medium;
                v.p = o + d * *scatterAt;
                v.medium = medium;
                v.g = mf->coefficients.g;
                v.beta = beta;
                v.rU = rU;
                v.emission = emission;
                v.pdfFwd = toArea(pdfDir, out.back(), v);
                out.push_back(v);
                if (++vertices >= maxVertices || !scatters) return;
                Vertex& cur = out.back();
                Vertex& before = out[out.size() - 2];
                // The dimensions of a surface's scattering: the lobe choice (none here),
                // the direction, the roulette.
                sampler.skip();
                const Vec3f wi = sampleHenyeyGreenstein(d, cur.g, sampler.get2D());
                // The phase function is its own density, the same both ways.
                pdfDir = henyeyGreenstein(glm::dot(d, wi), cur.g);
                before.pdfRev = toArea(pdfDir, cur, before);
                const float rrBeta = (beta / rU.average()).maxValue() / beta0;
                if (rouletteApplies(rrBeta, vertices, settings_.russianRouletteDepth)) {
                    if (!russianRoulette(beta, rrBeta, vertices, settings_.russianRouletteDepth,
                                         sampler.get1D()))
                        return;
                } else {
                    sampler.skip();
                }
                if (!beta.isFinite()) return;
                crossings = 0;
                o = cur.p;
                d = wi;
                continue;
            }
        }
        if (!hit) {
            if (!lightPath && !c_.lights.infiniteLights().empty()) {
                Vertex v;
                v.type = BdptVertexType::Light;
                v.infinite = true;
                v.p = d;
                v.beta = beta;
                v.pdfFwd = pdfDir;
                v.rU = rU;
                out.push_back(v);
            }
            return;
        }
        const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
        if (media_ && surface(*shape.desc).isInterface()) {
            // An index-matched boundary: the subpath goes straight on into the other medium;
            // not a vertex (the densities of the vertices on either side see through it).
            if (++crossings > kMaxInterfaceCrossings) return;
            medium = mediumAfter(shape, medium, hit->ng, d, d);
            o = offsetRayOrigin(hit->p, facing(hit->ng, d), c_.geometry.rayOffsetScale());
            continue;
        }
        Vertex v;
        v.p = hit->p;
        v.ng = hit->ng;
        v.ns = hit->ns;
        v.tangent = hit->tangent;
        v.uv = hit->uv;
        v.material = shape.material;
        v.light = c_.lights.lightAt(*hit);
        v.shape = hit->shape;
        v.medium = medium;
        v.beta = beta;
        v.rU = rU;
        v.pdfFwd = toArea(pdfDir, out.back(), v);
        out.push_back(v);
        Vertex& cur = out.back();
        Vertex& before = out[out.size() - 2];
        if (++vertices >= maxVertices) return;

        const ShadingPoint at(cur.p, cur.ng, cur.ns, -d, c_.geometry.rayOffsetScale(), cur.tangent);
        const Bxdf<S>& bsdf = mode_.bsdf(cur.material, {cur.uv, cur.p, cur.ng}, at.frame, path);
        const auto step =
            scatter(bsdf, at, bsdfMode, vertices, settings_.russianRouletteDepth, sampler, beta,
                    [&](S& b, const BsdfSample<S>& s, const Vec3f& wi) {
                        // A light subpath's matrices act in the order light meets them (the
                        // same product for the other modes' spectra, bit for bit).
                        if (lightPath) {
                            b = s.weight * b;
                            b *= ablations_.adjointCorrection(at.woWorld, wi, cur.ng, cur.ns);
                        } else {
                            b *= s.weight;
                        }
                        // The densities of this scattering both ways, for the MIS weights.
                        float pdfRev;
                        if (s.isSpecular()) {
                            cur.delta = true;
                            pdfDir = pdfRev = 0.0f;
                        } else {
                            pdfDir = s.pdf;
                            pdfRev = bsdf.pdf(s.wi, at.wo);
                        }
                        before.pdfRev = toArea(pdfRev, cur, before);
                        if constexpr (Mode::kRendersMedia) {
                            if (media_) return (b / rU.average()).maxValue() / beta0;
                        }
                        return b.maxValue() / beta0;
                    });
        if (!step.next) return;
        if (media_) {
            medium = mediumAfter(shape, medium, hit->ng, d, step.next->direction);
            crossings = 0;
        }
        o = step.next->origin;
        d = step.next->direction;
    }
}

template class BdptIntegrator<Rgb<float>>;
template class BdptIntegrator<SampledSpectrum<float>>;
template class BdptIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
