#include "lamina/integrators/bdpt_connection.h"

#include <limits>

#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/integrators/medium_transport.h"
#include "lamina/integrators/visibility.h"

namespace lamina::render {

/// The BSDF of surface vertex `v` for light arriving from `from` (a point, or a direction
/// when infinite) and leaving to `to`, in the subpath's transport mode, with the sides rule
/// and (light subpaths) the adjoint correction; the phase function of a medium vertex.
/// `wPrev` points to the subpath's previous vertex.
template <SpectrumType S>
S BdptConnector<S>::evalAt(const Vertex& v, const Vec3f& wPrev, const Vec3f& wNext,
                           bool lightSubpath, typename Mode::Path& path) const {
    // Light crosses a medium vertex from -wPrev to wNext (or from -wNext to wPrev: the same
    // angle); its sigma_s is in the vertex's throughput.
    if (v.type == BdptVertexType::Medium) return S(henyeyGreenstein(-glm::dot(wPrev, wNext), v.g));
    if (!sidesAgree(wPrev, wNext, v.ng, v.ns)) return S(0.0f);
    const Frame<float> frame = Frame<float>::fromNormalTangent(v.ns, v.tangent);
    const Bxdf<S>& bsdf = mode_.bsdf(v.material, {v.uv, v.p, v.ng}, frame, path);
    const Vec3f prev = frame.toLocal(wPrev), next = frame.toLocal(wNext);
    if (!lightSubpath) return bsdf.eval(prev, next, TransportMode::Radiance);
    S f = ablations_.connectionBsdf(bsdf, prev, next);
    f *= ablations_.adjointCorrection(wPrev, wNext, v.ng, v.ns);
    return f;
}

/// Radiance emitted by emitter vertex `v` towards `w`, received at `receiver` (which a portal's
/// environment needs: it is seen only through the portal).
template <SpectrumType S>
S BdptConnector<S>::emitted(const Vertex& v, const Vec3f& w, const Vec3f& receiver,
                            typename Mode::Path& path) const {
    if (v.infinite) {
        S Le(0.0f);
        for (std::size_t i : c_.lights.infiniteLights())
            Le += mode_.emission(c_.lights.light(i).environment(receiver, -w), path);
        return Le;
    }
    if (v.light < 0) return S(0.0f);
    SurfaceHit at;
    at.p = v.p;
    at.ng = at.ns = v.ng;
    return mode_.emission(c_.lights.light(std::size_t(v.light)).radiance(at, w), path);
}

template <SpectrumType S>
std::optional<Transmittance<S>> BdptConnector<S>::passes(const Vertex& from, const Vertex* before,
                                                         const Vertex& to, int hero,
                                                         typename Mode::Path& path,
                                                         PathStatistics& stats) const {
    if constexpr (Mode::kRendersMedia) {
        if (media_) {
            const Vec3f w = directionTo(from, to);
            int medium = from.medium;
            if (from.type == BdptVertexType::Surface)
                medium = mediumAfter(c_.geometry.shapes()[std::size_t(from.shape)], from.medium,
                                     from.ng, directionTo(*before, from), w);
            if (!to.infinite)
                return segmentTransmittance(c_.geometry, mode_, path, from.p, from.ng, to.p, to.ng,
                                            medium, hero, stats);
            const Vec3f origin =
                from.ng == Vec3f(0.0f)
                    ? from.p
                    : offsetRayOrigin(from.p, facing(from.ng, w), c_.geometry.rayOffsetScale());
            return shadowTransmittance(c_.geometry, mode_, path, origin, w,
                                       std::numeric_limits<float>::infinity(), medium, hero, stats);
        }
    }
    const bool visible = to.infinite
                             ? directionUnoccluded(c_.geometry, from.p, from.ng, to.p, stats)
                             : segmentUnoccluded(c_.geometry, from.p, from.ng, to.p, to.ng, stats);
    if (!visible) return std::nullopt;
    return Transmittance<S>{};
}

template <SpectrumType S>
S BdptConnector<S>::throughMedia(const S& value, [[maybe_unused]] const Transmittance<S>& T,
                                 [[maybe_unused]] const S& rUCamera,
                                 [[maybe_unused]] const S& rULight,
                                 [[maybe_unused]] int hero) const {
    if constexpr (Mode::kRendersMedia) {
        if (media_) return value * T.T / ablations_.channelDensity(rUCamera * rULight * T.rL, hero);
    }
    return value;
}

template <SpectrumType S>
BdptConnection<S> BdptConnector<S>::connect(const std::vector<Vertex>& lightPath, int s,
                                            const std::vector<Vertex>& cameraPath, int t, int hero,
                                            PixelSampler& sampler, typename Mode::Path& path,
                                            PathStatistics& stats) const {
    const Vertex& cv = cameraPath[std::size_t(t - 1)];
    Vertex sampled;  // the fresh vertex of s = 1 or t = 1
    BdptConnection<S> result;
    S& value = result.contribution;
    if (s == 0 && cv.type == BdptVertexType::Medium) {
        // The camera subpath's end is a point of an emitting medium: its emission there.
        if (!(cv.emission.maxValue() > 0.0f)) return result;
        value = throughMedia(cv.emission, Transmittance<S>{}, cv.rU, S(1.0f), hero);
    } else if (s == 0) {
        // The camera subpath's end is an emitter.
        if (!(cv.infinite || (cv.type == BdptVertexType::Surface && cv.light >= 0))) return result;
        const Vertex& prev = cameraPath[std::size_t(t - 2)];
        value = throughMedia(
            cv.beta * emitted(cv, cv.infinite ? -cv.p : directionTo(cv, prev), prev.p, path),
            Transmittance<S>{}, cv.rU, S(1.0f), hero);
    } else if (t == 1) {
        // Light vertex s-1 (a surface or medium vertex: s >= 2, since (1, 1) is skipped)
        // seen by the camera.
        const Vertex& lv = lightPath[std::size_t(s - 1)];
        if (lv.delta) return result;
        const auto cc =
            c_.camera.sampleConnection(lv.p, sampler.get2DIfUsed(!c_.camera.isPinhole()));
        if (!cc) return result;
        sampled.type = BdptVertexType::Camera;
        sampled.p = cc->lensPoint;
        sampled.beta = S(cc->importance / cc->pdf);
        result.splatAt = cc->raster;
        const Vertex& before = lightPath[std::size_t(s - 2)];
        const S f = evalAt(lv, directionTo(lv, before), cc->wi, true, path);
        if (f.maxValue() <= 0.0f) return result;
        // f before the light prefix: in the polarised mode a light subpath's matrices act in
        // the order light meets them (docs/polarisation.md, "Light paths").
        value = f * lv.beta * sampled.beta;
        result.toLens = cc->wi;
        const auto T = passes(lv, &before, sampled, hero, path, stats);
        if (!T) return BdptConnection<S>{};
        value = throughMedia(value, *T, S(1.0f), lv.rU, hero);
    } else if (s == 1) {
        // Next-event estimation: a fresh point on a light.
        if (!cv.scatters() || cv.delta) return result;
        // Without a light choose() can return (no lights, or only constant environments, which
        // next-event estimation leaves to the other strategies) both numbers are skipped, not
        // drawn, as the path integrator does: later dimensions keep their values.
        if (!c_.lights.nextEventChooses()) {
            sampler.skip();
            sampler.skip();
            return result;
        }
        const float uLight = sampler.get1DIfUsed(c_.lights.choiceReadsNumber());
        const Vec2f uPoint = sampler.get2D();
        const auto choice = c_.lights.choose(cv.p, cv.ns, uLight);
        if (!choice) return result;
        const std::size_t index = choice->index;
        const float pmf = choice->probability;
        const Light& light = c_.lights.light(index);
        const auto ls = light.sample(cv.p, uPoint);
        if (!ls || !(ls->pdf > 0.0f) || ls->radiance.isZero()) return result;
        sampled.type = BdptVertexType::Light;
        sampled.light = int(index);
        sampled.infinite = light.isInfinite();
        sampled.deltaLight = light.isDelta();
        sampled.p = sampled.infinite ? ls->wi : ls->point;
        sampled.ng = sampled.ns = (light.isDelta() || sampled.infinite) ? Vec3f(0.0f) : ls->normal;
        sampled.pdfFwd = mis_.pdfLightOrigin(sampled);
        const Vertex& before = cameraPath[std::size_t(t - 2)];
        const S f = evalAt(cv, directionTo(cv, before), ls->wi, false, path);
        if (f.maxValue() <= 0.0f) return result;
        sampled.beta = mode_.emission(ls->radiance, path) / (pmf * ls->pdf);
        value = cv.beta * f * sampled.beta;
        const auto T = passes(cv, &before, sampled, hero, path, stats);
        if (!T) return BdptConnection<S>{};
        value = throughMedia(value, *T, cv.rU, S(1.0f), hero);
    } else {
        // Both ends scatter (surface or medium vertices): connect them.
        const Vertex& lv = lightPath[std::size_t(s - 1)];
        if (!cv.scatters() || !lv.scatters() || cv.delta || lv.delta) return result;
        const Vec3f d = lv.p - cv.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return result;
        const Vec3f w = d / std::sqrt(dist2);
        const Vertex& before = cameraPath[std::size_t(t - 2)];
        const S fc = evalAt(cv, directionTo(cv, before), w, false, path);
        if (fc.maxValue() <= 0.0f) return result;
        const S fl = evalAt(lv, directionTo(lv, lightPath[std::size_t(s - 2)]), -w, true, path);
        if (fl.maxValue() <= 0.0f) return result;
        // The geometry term: the cosines are in f (a medium vertex has none), 1/d^2 here.
        value = cv.beta * fc * fl * lv.beta * (1.0f / dist2);
        const auto T = passes(cv, &before, lv, hero, path, stats);
        if (!T) return BdptConnection<S>{};
        value = throughMedia(value, *T, cv.rU, lv.rU, hero);
    }
    if (value.maxValue() <= 0.0f) return result;
    result.misWeight = mis_.weight(lightPath, s, cameraPath, t, sampled, path);
    return result;
}

template <SpectrumType S>
BdptConnection<S> BdptConnector<S>::connectVolumeLight(const std::vector<Vertex>& lightPath,
                                                       const std::vector<Vertex>& cameraPath, int t,
                                                       int hero, typename Mode::Path& path,
                                                       PathStatistics& stats) const {
    BdptConnection<S> result;
    const Vertex& lv = lightPath[0];
    const Vertex& cv = cameraPath[std::size_t(t - 1)];
    if (!cv.scatters() || cv.delta) return result;
    const Vec3f d = lv.p - cv.p;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return result;
    const Vec3f w = d / std::sqrt(dist2);
    const Vertex& before = cameraPath[std::size_t(t - 2)];
    const S fc = evalAt(cv, directionTo(cv, before), w, false, path);
    if (fc.maxValue() <= 0.0f) return result;
    // lv.beta is sigma_a Le / (P p(x)): isotropic emission per unit volume and solid angle; no
    // cosine at a point of a medium.
    S value = cv.beta * fc * lv.beta * (1.0f / dist2);
    const auto T = passes(cv, &before, lv, hero, path, stats);
    if (!T) return result;
    value = throughMedia(value, *T, cv.rU, lv.rU, hero);
    if (value.maxValue() <= 0.0f) return result;
    result.contribution = value;
    result.misWeight = mis_.weight(lightPath, 1, cameraPath, t, lv, path);
    return result;
}

template class BdptConnector<Rgb<float>>;
template class BdptConnector<SampledSpectrum<float>>;
template class BdptConnector<PolarisedSpectrum>;

}  // namespace lamina::render
