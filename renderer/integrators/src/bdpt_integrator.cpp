#include "lamina/integrators/bdpt_integrator.h"

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
      mis_(c_, mode_, setup.settings.mis),
      connector_(c_, mode_, ablations_, mis_) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> BdptIntegrator<S>::sample(const PixelSample<S>& ps) const {
    const CameraSample cs = sampleCamera(filter_, c_.camera, ps.sampler, ps.x, ps.y);
    thread_local std::vector<Vertex> cameraPath, lightPath;
    cameraPath.clear();
    lightPath.clear();
    const Vec3f rayDirection = generateCameraSubpath(cs, ps.sampler, ps.path, cameraPath, ps.stats);
    generateLightSubpath(ps.sampler, ps.path, lightPath, ps.stats);

    S L(0.0f);
    const int nc = int(cameraPath.size()), nl = int(lightPath.size());
    for (int t = 1; t <= nc; ++t) {
        for (int s = 0; s <= nl; ++s) {
            const int depth = s + t - 2;
            // (1, 1) would connect a light point to the lens: the emitter seen directly,
            // which (0, 2) already counts with weight 1 (pbrt-v3 does the same).
            if (depth < 0 || depth > settings_.maxDepth || (s == 1 && t == 1)) continue;
            const BdptConnection<S> c =
                connector_.connect(lightPath, s, cameraPath, t, ps.sampler, ps.path, ps.stats);
            if (c.contribution.maxValue() <= 0.0f || !c.contribution.isFinite()) continue;
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
                                               typename Mode::Path& path, std::vector<Vertex>& out,
                                               PathStatistics& stats) const {
    const auto ray = c_.camera.generateRay(cs.raster.x, cs.raster.y, cs.lens);
    Vertex v;
    v.type = BdptVertexType::Camera;
    v.p = ray.origin;
    v.beta = S(1.0f);
    out.push_back(v);
    const float pdfDir = c_.camera.rayPdf(ray.direction).direction;
    randomWalk(ray.origin, ray.direction, S(1.0f), pdfDir, settings_.maxDepth + 1,
               TransportMode::Radiance, sampler, path, out, stats);
    // Parallel rays (orthographic): the first vertex's density is the film's, projected.
    if (c_.camera.parallel() && out.size() > 1 && !out[1].infinite)
        out[1].pdfFwd = c_.camera.parallelPdf(out[1].ng, out[1].onSurface());
    return ray.direction;
}

template <SpectrumType S>
void BdptIntegrator<S>::generateLightSubpath(PixelSampler& sampler, typename Mode::Path& path,
                                             std::vector<Vertex>& out,
                                             PathStatistics& stats) const {
    const auto particle = startParticle(c_.lights, c_.geometry, mode_, sampler, path);
    if (!particle) return;
    const EmissionSample& e = particle->emission;
    const Light& light = c_.lights.light(particle->light);
    Vertex v;
    v.type = BdptVertexType::Light;
    v.light = int(particle->light);
    v.infinite = light.isInfinite();
    v.deltaLight = light.isDelta();
    v.p = v.infinite ? -e.direction : e.point;
    v.ng = v.ns = (e.deltaPosition || v.infinite) ? Vec3f(0.0f) : e.normal;
    v.beta = S(1.0f / (particle->pmf * e.pdfPosition));
    v.pdfFwd = mis_.pdfLightOrigin(v);
    out.push_back(v);

    const std::size_t first = out.size();
    randomWalk(particle->origin, e.direction, particle->beta, e.pdfDirection, settings_.maxDepth,
               TransportMode::Importance, sampler, path, out, stats);
    // From infinity the first vertex's density is the disk's, projected (not 1/d^2).
    if (v.infinite && out.size() > first) {
        Vertex& v1 = out[first];
        v1.pdfFwd = e.pdfPosition * std::abs(glm::dot(v1.ng, e.direction));
    }
}

/// Extends a subpath from its last vertex along (o, d) with throughput `beta` and the
/// solid-angle density `pdfDir` of d, until `maxSurfaces` surface vertices are added.
template <SpectrumType S>
void BdptIntegrator<S>::randomWalk(Vec3f o, Vec3f d, S beta, float pdfDir, int maxSurfaces,
                                   TransportMode mode, PixelSampler& sampler,
                                   typename Mode::Path& path, std::vector<Vertex>& out,
                                   PathStatistics& stats) const {
    const float beta0 = beta.maxValue();
    if (!(beta0 > 0.0f)) return;
    const bool lightPath = mode == TransportMode::Importance;
    const TransportMode bsdfMode = lightPath ? ablations_.lightPathMode() : mode;
    for (int surfaces = 0; surfaces < maxSurfaces; ++surfaces) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if (!hit) {
            if (!lightPath && !c_.lights.infiniteLights().empty()) {
                Vertex v;
                v.type = BdptVertexType::Light;
                v.infinite = true;
                v.p = d;
                v.beta = beta;
                v.pdfFwd = pdfDir;
                out.push_back(v);
            }
            return;
        }
        Vertex v;
        v.p = hit->p;
        v.ng = hit->ng;
        v.ns = hit->ns;
        v.uv = hit->uv;
        v.material = c_.geometry.shapes()[std::size_t(hit->shape)].material;
        v.light = c_.lights.lightAt(*hit);
        v.beta = beta;
        v.pdfFwd = toArea(pdfDir, out.back(), v);
        out.push_back(v);
        Vertex& cur = out.back();
        Vertex& before = out[out.size() - 2];
        if (surfaces + 1 >= maxSurfaces) return;

        const ShadingPoint at(cur.p, cur.ng, cur.ns, -d, c_.geometry.rayOffsetScale());
        const Bxdf<S>& bsdf = mode_.bsdf(cur.material, cur.uv, at.frame, path);
        const auto step =
            scatter(bsdf, at, bsdfMode, surfaces + 1, settings_.russianRouletteDepth, sampler, beta,
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
                        return b.maxValue() / beta0;
                    });
        if (!step.next) return;
        o = step.next->origin;
        d = step.next->direction;
    }
}

template class BdptIntegrator<Rgb<float>>;
template class BdptIntegrator<SampledSpectrum<float>>;
template class BdptIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
