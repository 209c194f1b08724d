#include "lamina/integrators/bdpt_mis.h"

#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/core/warp.h"
#include "lamina/integrators/grid_tracking.h"

namespace lamina::render {

/// Density (area measure at `next`) with which a light subpath starting at light vertex `v`
/// reaches `next`.
template <SpectrumType S>
float BdptMisWeights<S>::pdfLight(const Vertex& v, const Vertex& next) const {
    // A medium's emission leaves in a direction uniform on the sphere.
    if (inVolume(v)) return toArea(uniformSpherePdf<float>(), v, next);
    if (v.infinite) {
        // The density per unit area perpendicular to the direction, projected on the surface
        // at `next`. A directional light's is its disk's. The environments are one light at
        // infinity for the MIS weights (a camera subpath's escape does not say which one it
        // met): their particles' densities along the line through `next`, each light's
        // position density weighted by its share of the direction density (the disk's for
        // all of them without portals; a portal's only for lines through it). With the
        // direction density of pdfLightOrigin, the product is the sum over the environments of
        // the density of a particle from each on this line, which keeps the weights of every
        // strategy summing to one (portal_environment.h).
        const Vec3f d = -v.p;
        float position = 0.0f;
        if (v.light >= 0 && v.deltaLight) {
            position =
                c_.lights.light(std::size_t(v.light)).emissionPdf(next.p, Vec3f(0.0f), d).position;
        } else {
            float weighted = 0.0f, total = 0.0f;
            for (std::size_t i : c_.lights.infiniteLights()) {
                const Light& light = c_.lights.light(i);
                if (light.isDelta()) continue;
                const EmissionPdf e = light.emissionPdf(next.p, Vec3f(0.0f), d);
                const float share = emitters_.lightProbability(i) * e.direction;
                weighted += share * e.position;
                total += share;
            }
            position = total > 0.0f ? weighted / total : 0.0f;
        }
        return position * (next.onSurface() ? std::abs(glm::dot(next.ng, d)) : 1.0f);
    }
    const Light& light = c_.lights.light(std::size_t(v.light));
    const Vec3f d = directionTo(v, next);
    const EmissionPdf e = light.emissionPdf(v.p, v.ng, d);
    return toArea(e.direction, v, next);
}

template <SpectrumType S>
float BdptMisWeights<S>::pdfLightOrigin(const Vertex& v) const {
    if (inVolume(v))
        return emitters_.mediumProbability(v.medium) * emitters_.pointDensity(v.medium, v.p);
    if (v.infinite && v.deltaLight) return emitters_.lightProbability(std::size_t(v.light));
    if (v.infinite) return infiniteLightDensity(-v.p);
    const Light& light = c_.lights.light(std::size_t(v.light));
    return emitters_.lightProbability(std::size_t(v.light)) *
           light.emissionPdf(v.p, v.ng, Vec3f(0.0f, 0.0f, 1.0f)).position;
}

/// All environment lights start particles along `direction` (they cannot be told apart);
/// directional lights are deltas, never hit.
template <SpectrumType S>
float BdptMisWeights<S>::infiniteLightDensity(const Vec3f& direction) const {
    float pdf = 0.0f;
    for (std::size_t i : c_.lights.infiniteLights())
        if (!c_.lights.light(i).isDelta())
            pdf += emitters_.lightProbability(i) *
                   c_.lights.light(i).emissionPdf(Vec3f(0.0f), Vec3f(0.0f), direction).direction;
    return pdf;
}

template <SpectrumType S>
float BdptMisWeights<S>::selectionRatio(const Vertex& lightVertex, const Vertex& receiver) const {
    // A medium's emission is not sampled by next-event estimation: its strategy s = 1 connects
    // the light subpath's own first vertex, with the particle's density.
    if (inVolume(lightVertex)) return 1.0f;
    // An environment vertex of a camera path does not say which light it is: the ratio is the
    // same for all environments (LightSet), which are the lights at infinity that are not
    // delta.
    std::size_t i = lightVertex.light >= 0 ? std::size_t(lightVertex.light)
                                           : c_.lights.infiniteLights().front();
    if (lightVertex.light < 0)
        for (std::size_t k : c_.lights.infiniteLights())
            if (!c_.lights.light(k).isDelta()) {
                i = k;
                break;
            }
    return c_.lights.probability(i, receiver.p, receiver.ns) / emitters_.lightProbability(i);
}

template <SpectrumType S>
float BdptMisWeights<S>::volumeFactor(const Vertex& v, typename Mode::Path& path) const {
    if constexpr (Mode::kRendersMedia) {
        return coefficientsAtPoint(mode_.medium(v.medium, path), v.p).sigmaT.average();
    }
    return 1.0f;
}

/// Density (area at `next`) with which vertex `v`, reached from `prev`, samples `next`.
template <SpectrumType S>
float BdptMisWeights<S>::pdf(const Vertex& v, const Vertex* prev, const Vertex& next,
                             typename Mode::Path& path) const {
    if (v.type == BdptVertexType::Light) return pdfLight(v, next);
    const Vec3f wn = directionTo(v, next);
    if (v.type == BdptVertexType::Camera)
        return c_.camera.parallel() ? c_.camera.parallelPdf(next.ng, next.onSurface())
                                    : toArea(c_.camera.rayPdf(wn).direction, v, next);
    const Vec3f wp = directionTo(v, *prev);
    // A medium vertex samples its phase function, a density over directions of propagation
    // (from -wp to wn).
    if (v.type == BdptVertexType::Medium)
        return toArea(henyeyGreenstein(-glm::dot(wp, wn), v.g), v, next);
    const Frame<float> frame = Frame<float>::fromNormalTangent(v.ns, v.tangent);
    const Bxdf<S>& bsdf = mode_.bsdf(v.material, {v.uv, v.p, v.ng}, frame, path);
    return toArea(bsdf.pdf(frame.toLocal(wp), frame.toLocal(wn)), v, next);
}

namespace {

struct Densities {
    float pdfFwd, pdfRev;
    bool delta;
};

}  // namespace

/// 1 / (1 + sum over the other strategies of (p_other / p_this)^beta), the ratios accumulated
/// vertex by vertex outwards from the connection.
template <SpectrumType S>
float BdptMisWeights<S>::weight(const std::vector<Vertex>& lightPath, int s,
                                const std::vector<Vertex>& cameraPath, int t, const Vertex& sampled,
                                typename Mode::Path& path) const {
    if (s + t == 2) return 1.0f;
    thread_local std::vector<Densities> lightD, cameraD;
    lightD.resize(std::size_t(s));
    cameraD.resize(std::size_t(t));
    for (int i = 0; i < s; ++i)
        lightD[std::size_t(i)] = {lightPath[std::size_t(i)].pdfFwd,
                                  lightPath[std::size_t(i)].pdfRev,
                                  lightPath[std::size_t(i)].delta};
    for (int i = 0; i < t; ++i)
        cameraD[std::size_t(i)] = {cameraPath[std::size_t(i)].pdfFwd,
                                   cameraPath[std::size_t(i)].pdfRev,
                                   cameraPath[std::size_t(i)].delta};
    // The path's end vertices as this strategy sees them.
    const bool freshLight = s == 1 && t > 1;  // next-event estimation's own light point
    const Vertex& qs = freshLight || s == 0 ? sampled : lightPath[std::size_t(s - 1)];
    const Vertex& pt = t == 1 ? sampled : cameraPath[std::size_t(t - 1)];
    const Vertex* qsMinus = s > 1 ? &lightPath[std::size_t(s - 2)] : nullptr;
    const Vertex* ptMinus = t > 1 ? &cameraPath[std::size_t(t - 2)] : nullptr;
    if (freshLight) lightD[0] = {sampled.pdfFwd, lightD[0].pdfRev, false};
    if (t == 1) cameraD[0] = {cameraD[0].pdfFwd, cameraD[0].pdfRev, false};
    if (s > 0) lightD[std::size_t(s - 1)].delta = false;
    cameraD[std::size_t(t - 1)].delta = false;

    // Reverse densities at the connection.
    if (s > 0) {
        cameraD[std::size_t(t - 1)].pdfRev = pdf(qs, qsMinus, pt, path);
    } else {
        cameraD[std::size_t(t - 1)].pdfRev = pdfLightOrigin(pt);
    }
    if (ptMinus) {
        cameraD[std::size_t(t - 2)].pdfRev =
            s > 0 ? pdf(pt, &qs, *ptMinus, path) : pdfLight(pt, *ptMinus);
    }
    if (s > 0) lightD[std::size_t(s - 1)].pdfRev = pdf(pt, ptMinus, qs, path);
    if (qsMinus) lightD[std::size_t(s - 2)].pdfRev = pdf(qs, &pt, *qsMinus, path);

    const auto ratio = [this](float num, float den) {
        const float r = (num != 0.0f ? num : 1.0f) / (den != 0.0f ? den : 1.0f);
        return heuristic_ == MisHeuristic::Power ? r * r : r;
    };
    // The densities above choose the light vertex x0 as a particle does (emitterProbability);
    // next-event estimation (s = 1) chooses it from the surface vertex x1 next to it
    // (LightSet::probability; with no normal at a medium vertex). The term of strategy s = 1 is
    // scaled by the ratio of the two.
    const Vertex& x0 = s == 0 ? pt : s == 1 ? sampled : lightPath[0];
    const Vertex* x1 = s == 0 ? ptMinus : s == 1 ? &pt : &lightPath[1];
    // A path that ends in a medium's volume: the light side's density of its end x0 is per
    // unit volume, the camera side's (a phase function's or BSDF's, converted to area) is made
    // one by the factor volumeFactor, which depends on the path alone (not on the hero), so the
    // weights of the path's strategies still sum to one (docs/media.md).
    if (inVolume(x0)) {
        const float f = volumeFactor(x0, path);
        if (s == 0)
            cameraD[std::size_t(t - 1)].pdfFwd *= f;
        else
            lightD[0].pdfRev *= f;
    }
    float nextEvent = 1.0f;
    if (x1 && x1->scatters()) {
        const float q = selectionRatio(x0, *x1);
        nextEvent = heuristic_ == MisHeuristic::Power ? q * q : q;
    }
    float sum = 0.0f, r = 1.0f;
    for (int i = t - 1; i > 0; --i) {
        r *= ratio(cameraD[std::size_t(i)].pdfRev, cameraD[std::size_t(i)].pdfFwd);
        if (!cameraD[std::size_t(i)].delta && !cameraD[std::size_t(i - 1)].delta)
            sum += s == 0 && i == t - 1 ? r * nextEvent : r;
    }
    r = 1.0f;
    for (int i = s - 1; i >= 0; --i) {
        r *= ratio(lightD[std::size_t(i)].pdfRev, lightD[std::size_t(i)].pdfFwd);
        const bool deltaBefore = i > 0 ? lightD[std::size_t(i - 1)].delta
                                       : (freshLight ? sampled : lightPath[0]).deltaLight;
        if (!lightD[std::size_t(i)].delta && !deltaBefore) sum += i == 1 ? r * nextEvent : r;
    }
    // Strategy s = 1 itself: every other strategy's ratio to it is over its own density.
    if (s == 1 && nextEvent > 0.0f) sum /= nextEvent;
    return 1.0f / (1.0f + sum);
}

template class BdptMisWeights<Rgb<float>>;
template class BdptMisWeights<SampledSpectrum<float>>;
template class BdptMisWeights<PolarisedSpectrum>;

}  // namespace lamina::render
