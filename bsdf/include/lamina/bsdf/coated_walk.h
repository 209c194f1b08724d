// The random walks of CoatedBxdf (coated.h): sample() traces one exact path; estimate() runs
// the walk with next-event connections that estimates f |cos theta_i| and the density of
// sample() at a pair. Positions are heights z in [0, thickness] (base at 0, coat at
// thickness); `w` is always the direction the walk travels in.
#pragma once

#include "lamina/bsdf/coated.h"

namespace lamina {

template <SpectrumType S>
std::optional<BsdfSample<S>> CoatedBxdf<S>::sample(const V3& woIn, Float uc, const V2& u,
                                                   TransportMode mode) const {
    if (woIn.z == Float(0)) return std::nullopt;
    // Two-sided, like the analytic stack: seen from below, the coat is mirrored.
    const Float side = woIn.z < Float(0) ? Float(-1) : Float(1);
    const auto mirrored = [side](V3 w) {
        w.z *= side;
        return w;
    };
    const V3 wo = mirrored(woIn);
    auto entry = top_.bxdf().sample(wo, uc, u, mode);
    if (!entry) return std::nullopt;
    if (!entry->isTransmission()) {  // reflected by the coat: a path of one event
        entry->wi = mirrored(entry->wi);
        if (entry->isSpecular()) return entry;
        entry->pdf = pdf(woIn, entry->wi);
        if (!(entry->pdf > Float(0))) return std::nullopt;
        return entry;
    }
    Pcg32 rng(
        hashValues({seed_, 2, bits(uc), bits(u.x), bits(u.y), bits(wo.x), bits(wo.y), bits(wo.z)}));
    const auto u2 = [&rng] {
        const Float a = rng.next<Float>();
        return V2(a, rng.next<Float>());
    };
    S beta = entry->weight;
    V3 w = entry->wi;
    Float z = medium_.thickness;
    bool specular = entry->isSpecular(), diffuse = false;
    Float discrete = specular ? entry->pdf : Float(1);
    for (int depth = 0; withinDepth(depth); ++depth) {
        const Float q = survival(depth, beta);
        if (q < Float(1)) {
            if (rng.next<Float>() >= q) return std::nullopt;
            beta /= q;
            discrete *= q;
        }
        if (scattering()) {
            // A free flight of unit extinction along w: exponential in depth with mean |w.z|.
            const Float dz = -std::log1p(-rng.next<Float>()) * std::abs(w.z);
            const Float zp = w.z > Float(0) ? z + dz : z - dz;
            if (zp > Float(0) && zp < medium_.thickness) {
                z = zp;
                w = sampleHenyeyGreenstein(w, medium_.g, u2());
                beta *= medium_.albedo;
                specular = false;
                continue;
            }
        } else {
            beta *= transmittance(medium_.thickness, w);
        }
        const bool atTop = w.z > Float(0);
        z = atTop ? medium_.thickness : Float(0);
        if (!atTop) {
            const Float ucBase = rng.next<Float>();
            const auto b = base_->sample(-w, ucBase, u2(), mode);
            if (!b || b->isTransmission() || !(b->wi.z > Float(0))) return std::nullopt;
            beta *= b->weight;
            specular = specular && b->isSpecular();
            if (b->isSpecular()) discrete *= b->pdf;
            diffuse = diffuse || (b->flags & kLobeDiffuse) != 0;
            w = b->wi;
            continue;
        }
        const Float ucTop = rng.next<Float>();
        const auto t = top_.bxdf().sample(-w, ucTop, u2(), mode);
        if (!t) return std::nullopt;
        beta *= t->weight;
        specular = specular && t->isSpecular();
        if (t->isSpecular()) discrete *= t->pdf;
        w = t->wi;
        if (!t->isTransmission()) continue;
        // Out of the coat: the path's throughput is the sample's weight.
        if (!beta.isFinite() || beta.isZero()) return std::nullopt;
        const V3 wi = mirrored(w);
        if (specular) return BsdfSample<S>{wi, beta, discrete, kLobeSpecularReflection, Float(1)};
        const Float p = pdf(woIn, wi);
        if (!(p > Float(0))) return std::nullopt;
        return BsdfSample<S>{wi, beta, p, diffuse ? kLobeDiffuseReflection : kLobeGlossyReflection,
                             Float(1)};
    }
    return std::nullopt;
}

template <SpectrumType S>
typename CoatedBxdf<S>::Estimate CoatedBxdf<S>::estimate(V3 wo, V3 wi, TransportMode mode,
                                                         Pcg32& rng) const {
    Estimate e;
    if (!sameHemisphere(wo, wi)) return e;
    if (wo.z < Float(0)) {
        wo.z = -wo.z;
        wi.z = -wi.z;
    }
    for (int s = 0; s < samples_; ++s)
        walk(wo, wi, mode, rng, e);
    e.value /= Float(samples_);
    e.density /= Float(samples_);
    // The path of one event, reflection by the coat, is known in closed form.
    if (!top_.smooth()) {
        e.value += top_.bxdf().eval(wo, wi, mode);
        e.density += top_.bxdf().pdf(wo, wi);
    }
    if (!e.value.isFinite() || e.value.hasNegative()) e.value = S(Float(0));
    if (!std::isfinite(e.density) || e.density < Float(0)) e.density = Float(0);
    return e;
}

template <SpectrumType S>
void CoatedBxdf<S>::walk(const V3& wo, const V3& wi, TransportMode mode, Pcg32& rng,
                         Estimate& out) const {
    const auto u2 = [&rng] {
        const Float a = rng.next<Float>();
        return V2(a, rng.next<Float>());
    };
    const auto entry = top_.sampleTransmission(wo, u2(), mode);
    if (!entry) return;
    // wi is reached by travelling up along -exit->w: a refraction of wi sampled from outside
    // in the adjoint mode (f_mode(a, b) = f_adjoint(b, a), Veach 1997, eq. 5.14).
    const auto exit = top_.sampleTransmission(wi, u2(), adjoint(mode));
    const bool exitSmooth = top_.smooth();
    const Float absCosI = std::abs(wi.z);
    // Density of the full sampler leaving the coat towards wi from inside, along `up`, over the
    // density with which `exit` chose -up. Smooth: the Jacobian of refraction,
    // d omega_inside / d omega_outside = |cos_i| / (eta^2 |cos_up|) (conservation of etendue).
    const auto exitDensityRatio = [&](const V3& up) -> Float {
        if (!exitSmooth) return top_.bxdf().pdf(-up, wi) / exit->pdf;
        const Float eta = top_.bxdf().indexMatched() ? Float(1) : top_.eta();
        return exit->choice * absCosI / (sqr(eta) * std::abs(up.z));
    };

    S beta = entry->weight;                   // the walk's throughput
    S betaS = entry->weight / entry->choice;  // the throughput sample() has on the same path
    Float prob = entry->choice;               // probability of sample()'s branches over the walk's
    V3 w = entry->w;
    Float z = medium_.thickness;

    // Leaving the slab along `up` from height zFrom after event `depth`, which sampled `up` with
    // density pOther (0: a delta event, which next-event estimation cannot reach).
    const auto addSampledExit = [&](const V3& up, Float zFrom, int depth, Float pOther) {
        if (exitSmooth || !(up.z > Float(0)) || !withinDepth(depth + 1)) return;
        const S f = top_.bxdf().eval(-up, wi, mode);
        const Float p = top_.bxdf().pdf(-up, wi);
        if (f.isZero() && !(p > Float(0))) return;
        const Float wt =
            pOther > Float(0) ? power(pOther, top_.bxdf().refractionPdf(wi, -up)) : Float(1);
        const Float tr = transmittance(medium_.thickness - zFrom, up);
        out.value += beta * f * (tr * wt);
        out.density += prob * (scattering() ? tr : Float(1)) * survival(depth + 1, betaS) * p * wt;
    };

    for (int depth = 0; withinDepth(depth); ++depth) {
        const Float q = survival(depth, betaS);
        if (q < Float(1)) {
            if (rng.next<Float>() >= q) return;
            beta /= q;
            betaS /= q;
        }
        // The walk's own roulette: inside the coat it always reflects, so betaS (which
        // sample() would have) does not decay; what does is what the walk still adds, beta and
        // prob. Dividing both by the survival keeps both estimates unbiased.
        const Float own = survival(depth, S(std::max(beta.maxValue(), prob)));
        if (own < Float(1)) {
            if (rng.next<Float>() >= own) return;
            beta /= own;
            prob /= own;
        }
        if (scattering()) {
            const Float dz = -std::log1p(-rng.next<Float>()) * std::abs(w.z);
            const Float zp = w.z > Float(0) ? z + dz : z - dz;
            if (zp > Float(0) && zp < medium_.thickness) {
                z = zp;
                if (exit && withinDepth(depth + 1)) {
                    const V3 up = -exit->w;
                    const Float ph = henyeyGreenstein(glm::dot(w, up), medium_.g);
                    const Float wt = exitSmooth ? Float(1) : power(exit->pdf, ph);
                    const Float tr = transmittance(medium_.thickness - z, up);
                    out.value += beta * medium_.albedo * exit->weight *
                                 (ph * tr * wt * absCosI / std::abs(up.z));
                    out.density += prob * ph * tr * survival(depth + 1, betaS * medium_.albedo) *
                                   wt * exitDensityRatio(up);
                }
                const V3 next = sampleHenyeyGreenstein(w, medium_.g, u2());
                const Float ph = henyeyGreenstein(glm::dot(w, next), medium_.g);
                w = next;
                beta *= medium_.albedo;
                betaS *= medium_.albedo;
                addSampledExit(w, z, depth, ph);
                continue;
            }
        } else {
            const Float tr = transmittance(medium_.thickness, w);
            beta *= tr;
            betaS *= tr;
        }
        const bool atTop = w.z > Float(0);
        z = atTop ? medium_.thickness : Float(0);
        if (atTop) {  // back at the coat from inside: only reflection continues the walk
            const auto r = top_.sampleInternalReflection(-w, u2());
            if (!r) return;
            beta *= r->weight;
            betaS *= r->weight / r->choice;
            prob *= r->choice;
            w = r->w;
            continue;
        }
        if (exit && withinDepth(depth + 1)) {  // next-event connection from the base
            const V3 up = -exit->w;
            const S fb = base_->eval(-w, up, mode);
            const Float pb = base_->pdf(-w, up);
            const Float wt = exitSmooth ? Float(1) : power(exit->pdf, pb);
            const Float tr = transmittance(medium_.thickness, up);
            out.value += beta * fb * exit->weight * (tr * wt * absCosI / std::abs(up.z));
            if (pb > Float(0))
                out.density += prob * pb * (scattering() ? tr : Float(1)) *
                               survival(depth + 1, betaS * fb / pb) * wt * exitDensityRatio(up);
        }
        const Float ucBase = rng.next<Float>();
        const auto b = base_->sample(-w, ucBase, u2(), mode);
        if (!b || b->isTransmission() || !(b->wi.z > Float(0))) return;
        beta *= b->weight;
        betaS *= b->weight;
        w = b->wi;
        addSampledExit(w, z, depth, b->isSpecular() ? Float(0) : b->pdf);
    }
}

}  // namespace lamina
