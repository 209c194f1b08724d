#include "lamina/integrators/bdpt_connection.h"

#include "lamina/integrators/visibility.h"

namespace lamina::render {

/// The BSDF of surface vertex `v` for light arriving from `from` (a point, or a direction
/// when infinite) and leaving to `to`, in the subpath's transport mode, with the sides rule
/// and (light subpaths) the adjoint correction. `wPrev` points to the subpath's previous
/// vertex.
template <SpectrumType S>
S BdptConnector<S>::evalAt(const Vertex& v, const Vec3f& wPrev, const Vec3f& wNext,
                           bool lightSubpath, typename Mode::Path& path) const {
    if (!sidesAgree(wPrev, wNext, v.ng, v.ns)) return S(0.0f);
    const Frame<float> frame = Frame<float>::fromNormal(v.ns);
    const Bxdf<S>& bsdf = mode_.bsdf(v.material, v.uv, frame, path);
    const Vec3f prev = frame.toLocal(wPrev), next = frame.toLocal(wNext);
    if (!lightSubpath) return bsdf.eval(prev, next, TransportMode::Radiance);
    S f = ablations_.connectionBsdf(bsdf, prev, next);
    f *= ablations_.adjointCorrection(wPrev, wNext, v.ng, v.ns);
    return f;
}

/// Radiance emitted by emitter vertex `v` towards `w`.
template <SpectrumType S>
S BdptConnector<S>::emitted(const Vertex& v, const Vec3f& w, typename Mode::Path& path) const {
    if (v.infinite) {
        S Le(0.0f);
        for (std::size_t i : c_.lights.infiniteLights())
            Le += mode_.emission(c_.lights.light(i).environment(-w), path);
        return Le;
    }
    if (v.light < 0) return S(0.0f);
    SurfaceHit at;
    at.p = v.p;
    at.ng = at.ns = v.ng;
    return mode_.emission(c_.lights.light(std::size_t(v.light)).radiance(at, w), path);
}

template <SpectrumType S>
bool BdptConnector<S>::unoccluded(const Vertex& a, const Vertex& b, PathStatistics& stats) const {
    return segmentUnoccluded(c_.geometry, a.p, a.ng, b.p, b.ng, stats);
}

template <SpectrumType S>
BdptConnection<S> BdptConnector<S>::connect(const std::vector<Vertex>& lightPath, int s,
                                            const std::vector<Vertex>& cameraPath, int t,
                                            PixelSampler& sampler, typename Mode::Path& path,
                                            PathStatistics& stats) const {
    const Vertex& cv = cameraPath[std::size_t(t - 1)];
    Vertex sampled;  // the fresh vertex of s = 1 or t = 1
    BdptConnection<S> result;
    S& value = result.contribution;
    if (s == 0) {
        // The camera subpath's end is an emitter.
        if (!(cv.infinite || (cv.type == BdptVertexType::Surface && cv.light >= 0))) return result;
        const Vertex& prev = cameraPath[std::size_t(t - 2)];
        value = cv.beta * emitted(cv, cv.infinite ? -cv.p : directionTo(cv, prev), path);
    } else if (t == 1) {
        // Light vertex s-1 (a surface: s >= 2, since (1, 1) is skipped) seen by the camera.
        const Vertex& lv = lightPath[std::size_t(s - 1)];
        if (lv.delta) return result;
        const auto cc =
            c_.camera.sampleConnection(lv.p, sampler.get2DIfUsed(!c_.camera.isPinhole()));
        if (!cc) return result;
        sampled.type = BdptVertexType::Camera;
        sampled.p = cc->lensPoint;
        sampled.beta = S(cc->importance / cc->pdf);
        result.splatAt = cc->raster;
        const Vec3f wPrev = directionTo(lv, lightPath[std::size_t(s - 2)]);
        const S f = evalAt(lv, wPrev, cc->wi, true, path);
        if (f.maxValue() <= 0.0f) return result;
        // f before the light prefix: in the polarised mode a light subpath's matrices act in
        // the order light meets them (docs/polarisation.md, "Light paths").
        value = f * lv.beta * sampled.beta;
        result.toLens = cc->wi;
        if (!unoccluded(lv, sampled, stats)) return BdptConnection<S>{};
    } else if (s == 1) {
        // Next-event estimation: a fresh point on a light.
        if (cv.type != BdptVertexType::Surface || cv.delta) return result;
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
        const Vec3f wPrev = directionTo(cv, cameraPath[std::size_t(t - 2)]);
        const S f = evalAt(cv, wPrev, ls->wi, false, path);
        if (f.maxValue() <= 0.0f) return result;
        sampled.beta = mode_.emission(ls->radiance, path) / (pmf * ls->pdf);
        value = cv.beta * f * sampled.beta;
        const bool visible = sampled.infinite
                                 ? directionUnoccluded(c_.geometry, cv.p, cv.ng, ls->wi, stats)
                                 : unoccluded(cv, sampled, stats);
        if (!visible) return BdptConnection<S>{};
    } else {
        // Both ends are surface vertices: connect them.
        const Vertex& lv = lightPath[std::size_t(s - 1)];
        if (cv.type != BdptVertexType::Surface || lv.type != BdptVertexType::Surface || cv.delta ||
            lv.delta)
            return result;
        const Vec3f d = lv.p - cv.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return result;
        const Vec3f w = d / std::sqrt(dist2);
        const S fc = evalAt(cv, directionTo(cv, cameraPath[std::size_t(t - 2)]), w, false, path);
        if (fc.maxValue() <= 0.0f) return result;
        const S fl = evalAt(lv, directionTo(lv, lightPath[std::size_t(s - 2)]), -w, true, path);
        if (fl.maxValue() <= 0.0f) return result;
        value = cv.beta * fc * fl * lv.beta * (1.0f / dist2);
        if (!unoccluded(cv, lv, stats)) return BdptConnection<S>{};
    }
    if (value.maxValue() <= 0.0f) return result;
    result.misWeight = mis_.weight(lightPath, s, cameraPath, t, sampled, path);
    return result;
}

template class BdptConnector<Rgb<float>>;
template class BdptConnector<SampledSpectrum<float>>;
template class BdptConnector<PolarisedSpectrum>;

}  // namespace lamina::render
