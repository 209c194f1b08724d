// The dielectric boundary on top of a coated material, as its random walk uses it (Guo, Hasan
// and Zhao 2018, "Position-Free Monte Carlo Simulation for Arbitrary Layered BSDFs", ACM TOG
// 37(6), section 4: every event is a BSDF sample of one interface). Besides the full BSDF
// (DielectricBxdf: reflection or refraction chosen by the Fresnel reflectance) the walk needs
// two restricted samplers, each returning how likely the full sampler was to take the same
// branch (`choice`), so that the walk can also estimate the density of the full sampler:
//   transmission only, from either side: weight (1 - F) T |cos| / p_refraction, choice 1 - F;
//   reflection only, from inside: weight F D G2 / (4 |cos_o|) / p_reflection, choice F.
// For the smooth boundary the weights are those of the delta lobes (DielectricBxdf::sample).
#pragma once

#include "lamina/bsdf/dielectric.h"

namespace lamina {

template <SpectrumType S>
class CoatInterface {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;
    using Distribution = MicrofacetDistribution<Float>;

    /// One restricted sample: the direction (away from the boundary), f |cos| / pdf of the
    /// restricted sampler, its density (1 for a delta lobe), and the probability with which
    /// the full sampler would have chosen the same branch.
    struct Event {
        V3 w;
        S weight;
        Float pdf = 0;
        Float choice = 0;
    };

    CoatInterface(Float eta, const Distribution& distribution, G2Form g2)
        : bxdf_(eta, distribution, g2), distribution_(distribution) {}

    const DielectricBxdf<S>& bxdf() const { return bxdf_; }
    bool smooth() const { return bxdf_.isSmooth(); }
    Float eta() const { return bxdf_.eta(); }

    /// Refraction of `w` (either side), nullopt under total internal reflection.
    std::optional<Event> sampleTransmission(const V3& w, const V2& u, TransportMode mode) const {
        const auto t = bxdf_.sampleRefraction(w, u);
        if (!t) return std::nullopt;
        const V3 wt = t->first;
        if (smooth()) {
            const Float T =
                bxdf_.indexMatched() ? Float(1) : Float(1) - fresnelDielectric(w.z, bxdf_.eta());
            if (!(T > Float(0))) return std::nullopt;
            const Float scale =
                mode == TransportMode::Radiance ? Float(1) / sqr(t->second) : Float(1);
            return Event{wt, S(T * scale), Float(1), T};
        }
        const Float p = bxdf_.refractionPdf(w, wt);
        if (!(p > Float(0))) return std::nullopt;
        const auto g = bxdf_.transmissionWithoutFresnel(w, wt, mode);
        const Float T = Float(1) - fresnelDielectric(glm::dot(w, g.m), bxdf_.eta());
        const S weight = S(g.value * T / p);
        if (!(T > Float(0)) || !weight.isFinite()) return std::nullopt;
        return Event{wt, weight, p, T};
    }

    /// Reflection of `w` (inside the coat, w.z < 0) back into the coat.
    std::optional<Event> sampleInternalReflection(const V3& w, const V2& u) const {
        if (smooth()) {
            const Float R = bxdf_.indexMatched() ? Float(0) : fresnelDielectric(w.z, bxdf_.eta());
            if (!(R > Float(0))) return std::nullopt;
            return Event{V3(-w.x, -w.y, w.z), S(R), Float(1), R};
        }
        const V3 m = distribution_.sampleVisibleNormal(-w, u);
        const V3 wr = reflect(w, m);
        if (!sameHemisphere(w, wr)) return std::nullopt;
        const Float wm = std::abs(glm::dot(w, m));
        const Float p = distribution_.visibleNormalPdf(-w, m) / (Float(4) * wm);
        if (!(p > Float(0))) return std::nullopt;
        const S weight = bxdf_.eval(w, wr, TransportMode::Radiance) / p;
        const Float R = fresnelDielectric(glm::dot(w, m), bxdf_.eta());
        if (!(R > Float(0)) || !weight.isFinite()) return std::nullopt;
        return Event{wr, weight, p, R};
    }

  private:
    DielectricBxdf<S> bxdf_;
    Distribution distribution_;
};

}  // namespace lamina
