#include "lamina/integrators/light_integrator.h"

#include <limits>

#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/integrators/medium_transport.h"
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
      ablations_(setup.ablations),
      media_(Mode::kRendersMedia && setup.context.scene.hasMedia()),
      emitters_(setup.context, media_) {}

template <SpectrumType S>
std::optional<CameraEstimate<S>> LightIntegrator<S>::sample(const PixelSample<S>& ps) const {
    traceParticle(ps.sampler, ps.path, ps.film, ps.stats);
    return std::nullopt;
}

template <SpectrumType S>
void LightIntegrator<S>::traceParticle(PixelSampler& sampler, typename Mode::Path& path, Film& film,
                                       PathStatistics& stats) const {
    const auto particle = startParticle(c_.lights, c_.geometry, mode_, sampler, path, emitters_);
    if (!particle) return;
    const EmissionSample& e = particle->emission;
    // A particle of a medium's emission has no light (medium_emitters.h).
    const bool fromVolume = particle->medium >= 0;
    const Light* light = fromVolume ? nullptr : &c_.lights.light(particle->light);

    // With media (medium_transport.h): the medium the particle is in, its hero channel, and
    // the densities of the particle's path per channel relative to the hero's (rU). A camera
    // connection's transmittance is exact and has no density of its own: it is traced from
    // the lens, which sits in the camera's medium.
    int medium = -1, hero = 0, crossings = 0;
    S rU(1.0f);
    const int cameraMedium = c_.scene.camera.medium;
    // Whether the lens sees p (normal n; zero for a medium vertex); with media, T gets the
    // connection's transmittance (ratio-tracked in grid media, with its densities).
    const auto lensSees = [&](const Vec3f& lens, const Vec3f& p, const Vec3f& n,
                              [[maybe_unused]] Transmittance<S>& T) {
        if constexpr (Mode::kRendersMedia) {
            if (media_) {
                const auto t = segmentTransmittance(c_.geometry, mode_, path, lens, Vec3f(0.0f), p,
                                                    n, cameraMedium, hero, stats);
                if (t) T = *t;
                return t.has_value();
            }
        }
        return segmentUnoccluded(c_.geometry, p, n, lens, Vec3f(0.0f), stats);
    };
    // A contribution through media: times the connection's transmittance, over the density of
    // the particle path and of the connection's tracking, averaged over the channels (the
    // balance heuristic of medium_transport.h; the tracking's densities are 1 through
    // homogeneous media).
    const auto throughMedia = [&](const S& value, [[maybe_unused]] const Transmittance<S>& T) {
        if constexpr (Mode::kRendersMedia) {
            if (media_) return S(value * T.T / ablations_.channelDensity(rU * T.rL, hero));
        }
        return value;
    };
    S beta = particle->beta;
    if constexpr (Mode::kRendersMedia) {
        if (media_) {
            hero = heroChannel<S>(sampler.get1D());
            // The particle starts in the medium of the side it leaves to: found from the
            // camera, through every boundary on the way to its first ray's origin (which is
            // off the emitting surface on that side).
            medium = mediumAt(c_.geometry, cameraMedium, Vec3f(c_.scene.camera.position),
                              particle->origin, stats);
            // A point of an emitting medium's box that is not in the medium carries nothing
            // (one try: the density stays the box's).
            if (fromVolume && medium != particle->medium) return;
            // Light from infinity through a medium that reaches infinity: none gets through
            // where the extinction is not 0, as for the path integrator's escaping rays.
            if (light && light->isInfinite() && medium >= 0)
                fromInfinity(mode_, path, medium, hero, particle->origin, e.direction, beta, rU);
        }
    }

    // The emitter itself seen by the camera (no scattering).
    const Vec2f uLens = sampler.get2DIfUsed(!c_.camera.isPinhole());
    if (particle->onSurface) {
        if (const auto cc = c_.camera.sampleConnection(e.point, uLens)) {
            SurfaceHit at;
            at.p = e.point;
            at.ng = at.ns = facing(e.normal, e.normal);
            const Emission toCamera = light->radiance(at, cc->wi);
            Transmittance<S> T;
            if (!toCamera.isZero() && lensSees(cc->lensPoint, e.point, e.normal, T)) {
                const float cosLight = std::abs(glm::dot(e.normal, cc->wi));
                const S value =
                    mode_.emission(toCamera, path) *
                    (cosLight * cc->importance / (cc->pdf * particle->pmf * e.pdfPosition));
                splatContribution(film, filter_, cc->raster, mode_, throughMedia(value, T), cc->wi,
                                  c_.camera.imageRight(), path);
            }
        }
    } else if (fromVolume) {
        // The medium's emission seen by the camera: sigma_a Le, isotropic, per unit volume
        // (no cosine at a point of a medium).
        if (const auto cc = c_.camera.sampleConnection(e.point, uLens)) {
            Transmittance<S> T;
            if (lensSees(cc->lensPoint, e.point, Vec3f(0.0f), T)) {
                const S value = particle->volumeEmission *
                                (cc->importance / (cc->pdf * particle->pmf * e.pdfPosition));
                splatContribution(film, filter_, cc->raster, mode_, throughMedia(value, T), cc->wi,
                                  c_.camera.imageRight(), path);
            }
        }
    }

    const float beta0 = beta.maxValue();
    if (!(beta0 > 0.0f) || !beta.isFinite()) return;
    Vec3f o = particle->origin, d = e.direction;
    const TransportMode mode = ablations_.lightPathMode();
    for (int bounces = 1; bounces <= settings_.maxDepth;) {
        ++stats.rays;
        const auto hit = c_.geometry.intersect(o, d);
        if constexpr (Mode::kRendersMedia) {
            const auto mf =
                media_ ? sampleMediumFlight(mode_, path, medium, hero, sampler, hit) : std::nullopt;
            // The flight passes, ends, or scatters at a medium vertex (medium_transport.h).
            std::optional<float> scatterAt;
            if (mf) {
                const FlightOutcome f =
                    mf->apply(o, d, hero, beta, rU, nullptr, nullptr, ablations_);
                if (f.outcome == FlightOutcome::Outcome::Ends) break;
                if (f.outcome == FlightOutcome::Outcome::Scatters) scatterAt = f.t;
            }
            if (scatterAt) {
                const MediumCoefficients<S>& m = mf->coefficients;
                // A medium vertex (its sigma_s is in beta already).
                if (!(beta.maxValue() > 0.0f)) break;
                const Vec3f p = o + d * *scatterAt;
                // Connection to the camera: the light leaves along d, reaches the lens
                // along cc->wi; the phase function of the angle between them.
                const Vec2f uCamera = sampler.get2DIfUsed(!c_.camera.isPinhole());
                if (const auto cc = c_.camera.sampleConnection(p, uCamera)) {
                    const float phase = henyeyGreenstein(glm::dot(d, cc->wi), m.g);
                    Transmittance<S> T;
                    if (phase > 0.0f && lensSees(cc->lensPoint, p, Vec3f(0.0f), T)) {
                        const S value = beta * (phase * cc->importance / cc->pdf);
                        splatContribution(film, filter_, cc->raster, mode_, throughMedia(value, T),
                                          cc->wi, c_.camera.imageRight(), path);
                    }
                }
                if (bounces == settings_.maxDepth) break;
                const Vec3f wi = sampleHenyeyGreenstein(d, m.g, sampler.get2D());
                const float rrBeta = (beta / rU.average()).maxValue() / beta0;
                if (rouletteApplies(rrBeta, bounces, settings_.russianRouletteDepth)) {
                    if (!russianRoulette(beta, rrBeta, bounces, settings_.russianRouletteDepth,
                                         sampler.get1D()))
                        break;
                } else {
                    sampler.skip();
                }
                if (!beta.isFinite()) break;
                crossings = 0;
                o = p;
                d = wi;
                ++bounces;
                continue;
            }
        }
        if (!hit) break;
        const ShapeInfo& shape = c_.geometry.shapes()[std::size_t(hit->shape)];
        if (media_ && surface(*shape.desc).isInterface()) {
            // An index-matched boundary: no scattering event, the particle goes on into the
            // medium on the other side.
            if (++crossings > kMaxInterfaceCrossings) break;
            medium = mediumAfter(shape, medium, hit->ng, d, d);
            o = offsetRayOrigin(hit->p, facing(hit->ng, d), c_.geometry.rayOffsetScale());
            continue;
        }
        const ShadingPoint at(hit->p, hit->ng, hit->ns, -d, c_.geometry.rayOffsetScale(),
                              hit->tangent);  // wo towards the light's side
        const Bxdf<S>& bsdf =
            mode_.bsdf(shape.material, {hit->uv, hit->p, hit->ng}, at.frame, path);

        // Connection to the camera.
        const Vec2f uCamera = sampler.get2DIfUsed(!c_.camera.isPinhole());
        if ((bsdf.flags() & (kLobeDiffuse | kLobeGlossy)) != 0) {
            if (const auto cc = c_.camera.sampleConnection(hit->p, uCamera);
                cc && sidesAgree(at.woWorld, cc->wi, hit->ng, hit->ns)) {
                const Vec3f toCamera = at.frame.toLocal(cc->wi);
                const S f = ablations_.connectionBsdf(bsdf, at.wo, toCamera) *
                            ablations_.adjointCorrection(at.woWorld, cc->wi, hit->ng, hit->ns);
                Transmittance<S> T;
                if (f.maxValue() > 0.0f && lensSees(cc->lensPoint, hit->p, hit->ng, T)) {
                    // f before beta: in the polarised mode the light path's matrices act
                    // in the order light meets them (docs/polarisation.md, "Light paths").
                    const S value = f * beta * (cc->importance / cc->pdf);
                    splatContribution(film, filter_, cc->raster, mode_, throughMedia(value, T),
                                      cc->wi, c_.camera.imageRight(), path);
                }
            }
        }
        if (bounces == settings_.maxDepth) break;

        // Russian roulette on the throughput relative to the particle's start (and to the
        // path's density, its average over the channels, with media).
        const auto step = scatter(
            bsdf, at, mode, bounces, settings_.russianRouletteDepth, sampler, beta,
            [&](S& b, const BsdfSample<S>& s, const Vec3f& wi) {
                b = s.weight * ablations_.adjointCorrection(at.woWorld, wi, hit->ng, hit->ns) * b;
                if constexpr (Mode::kRendersMedia) {
                    if (media_) return (b / rU.average()).maxValue() / beta0;
                }
                return b.maxValue() / beta0;
            });
        if (!step.next) break;
        if (media_) {
            medium = mediumAfter(shape, medium, hit->ng, d, step.next->direction);
            crossings = 0;
        }
        o = step.next->origin;
        d = step.next->direction;
        ++bounces;
    }
}

template class LightIntegrator<Rgb<float>>;
template class LightIntegrator<SampledSpectrum<float>>;
template class LightIntegrator<PolarisedSpectrum>;

}  // namespace lamina::render
