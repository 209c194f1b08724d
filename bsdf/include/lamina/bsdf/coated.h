// `coated`: a dielectric coat (smooth or rough, index `eta`) over a base BSDF without
// transmission, with an optional homogeneous medium between them (optical thickness
// `thickness` at unit extinction, single-scattering `albedo`, Henyey-Greenstein `g`).
//
// Light bounces between the two boundaries any number of times, so f has no closed form: it is
// estimated by the position-free random walk of Guo, Hasan and Zhao 2018 ("Position-Free Monte
// Carlo Simulation for Arbitrary Layered BSDFs", ACM TOG 37(6)). A path is a sequence of
// directions only (the slab is laterally infinite and homogeneous); its contribution is the
// product of the interface terms f |cos| and of the transmittance exp(-d / |cos|) over each
// vertical distance d (their eq. 5 and 6). The walk starts from wo, and at every event inside
// the slab connects to wi (next-event estimation through the top boundary, sampled from wi's
// side with the adjoint transport mode) and also continues by sampling the event's own BSDF; the
// two ways of reaching wi are combined by the power heuristic (their section 5.2).
//
//   sample(): traces one exact path (the full samplers of every event, Russian roulette on the
//     throughput after 4 events, see survival(); no depth limit unless the material sets
//     max_depth); its weight, the path throughput, is an unbiased estimate of eval / p where p
//     is the true density of the returned wi.
//   eval(), pdf(): one walk (repeated `samples` times) estimates both f |cos| and the true
//     density p of sample() at wi. The walk uses the same samplers, roulette and depth limit as
//     sample(), except that at the entry it always refracts and inside the top boundary it
//     always reflects; it keeps the probability that sample() would have taken those branches,
//     so that the same path weighted by probabilities instead of f |cos| estimates p without
//     bias. pdf() returns 0.9 p^ + 0.1 / (2 pi) (see docs/bsdf.md, "coated").
//
// The walk's random numbers come from a PCG32 seeded by a hash of (seed, wo, wi) and a stream
// per function: eval and pdf estimates at the same pair are independent, and both are the same
// at every call with the same arguments, so MIS weights computed by different strategies for
// the same path agree and sum to one, whatever the thread count.
#pragma once

#include <bit>
#include <memory>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/coat_interface.h"
#include "lamina/bsdf/henyey_greenstein.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"

namespace lamina {

/// The most events a coated walk may take: the largest `max_depth`, and the safeguard of a
/// walk without one (CoatedBxdf::withinDepth).
inline constexpr int kMaxCoatedDepth = 1 << 20;

template <SpectrumType S>
class CoatedBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    /// The slab between the coat and the base. thickness 0: no medium.
    struct Medium {
        Float thickness = 0;
        S albedo = S(Float(0));
        Float g = 0;
    };

    /// One walk's estimates at (wo, wi): f |cos theta_i| and the density of sample().
    struct Estimate {
        S value = S(Float(0));
        Float density = 0;
    };

    /// maxDepth: the most events of a walk (a longer path is absorbed, which biases f low);
    /// 0: none, the walk ends by Russian roulette and by leaving the coat.
    CoatedBxdf(const CoatInterface<S>& top, std::unique_ptr<Bxdf<S>> base, const Medium& medium,
               int maxDepth, int samples, std::uint64_t seed = 0)
        : top_(top),
          base_(std::move(base)),
          medium_(medium),
          maxDepth_(maxDepth),
          samples_(samples),
          seed_(seed) {}

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        if (!continuous() || !sameHemisphere(wo, wi)) return S(Float(0));
        Pcg32 rng(hashPair(wo, wi, 0));
        return estimate(wo, wi, mode, rng).value;
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (!continuous() || !sameHemisphere(wo, wi)) return Float(0);
        Pcg32 rng(hashPair(wo, wi, 1));
        // The density of sample() depends on the transport mode only through the roulette,
        // which sees the throughput: the radiance walk is the one estimated.
        const Float p = estimate(wo, wi, TransportMode::Radiance, rng).density;
        return Float(0.9) * p + Float(0.1) * kInvPi<Float> * Float(0.5);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override;

    std::uint32_t flags() const override {
        std::uint32_t f = top_.smooth() ? kLobeSpecularReflection : kLobeGlossyReflection;
        f |= reflectionKinds(base_->flags());
        if (scattering()) f |= kLobeGlossyReflection;
        return f;
    }

    /// The average of `samples` walks from `rng` (eval and pdf seed it from the directions;
    /// tests pass their own to average independent estimates). wo and wi on the same side.
    Estimate estimate(V3 wo, V3 wi, TransportMode mode, Pcg32& rng) const;

    /// The cap on a walk's events, 0 for none (unbiased).
    int maxDepth() const { return maxDepth_; }

    /// True when some path through the stack is not a chain of delta events: eval and pdf are
    /// zero otherwise.
    bool continuous() const {
        return !top_.smooth() || scattering() ||
               (base_->flags() & (kLobeDiffuse | kLobeGlossy)) != 0;
    }

  private:
    bool scattering() const { return medium_.thickness > Float(0) && !medium_.albedo.isZero(); }

    // exp(-dz / |cos|) over a vertical distance dz at unit extinction (Guo et al., eq. 6).
    Float transmittance(Float dz, const V3& w) const {
        if (medium_.thickness == Float(0) || dz == Float(0)) return Float(1);
        return std::exp(-std::abs(dz) / std::max(std::abs(w.z), Float(1e-8)));
    }

    // Survival probability of the Russian roulette before event `depth` with throughput beta
    // (Arvo and Kirk 1990, "Particle Transport and Image Synthesis", SIGGRAPH '90: a path
    // survives with probability q and its weight is divided by q, which leaves every estimate
    // unbiased). The first four events always survive; after them a path whose largest
    // channel m has fallen below kRouletteThreshold survives with probability m, so a
    // survivor's weight returns to about 1. The floor kRouletteFloor bounds the factor 1/q by
    // which a survivor's weight grows, whatever throughput the roulette reads (eval's walk
    // divides its own throughput by the roulette sample() plays on another one): the weights,
    // and so the variance, stay bounded. A throughput of zero ends the path (q = 0).
    static constexpr Float kRouletteThreshold = Float(0.25);
    static constexpr Float kRouletteFloor = Float(0.05);
    static Float survival(int depth, const S& beta) {
        if (depth <= 3) return Float(1);
        const Float m = beta.maxValue();
        if (!(m > Float(0))) return Float(0);
        return m < kRouletteThreshold ? std::max(m, kRouletteFloor) : Float(1);
    }

    // True while event `depth` is within the cap (always without one). kMaxCoatedDepth stops a
    // walk that would practically never end (a medium thousands of mean free paths thick that
    // absorbs nothing): no stack of the tests or the shipped scenes comes within orders of
    // magnitude of it (docs/bsdf.md, "coated").
    bool withinDepth(int depth) const {
        return depth < (maxDepth_ > 0 ? maxDepth_ : kMaxCoatedDepth);
    }

    static TransportMode adjoint(TransportMode mode) {
        return mode == TransportMode::Radiance ? TransportMode::Importance
                                               : TransportMode::Radiance;
    }

    static std::uint64_t bits(Float x) {
        if constexpr (std::is_same_v<Float, double>)
            return std::bit_cast<std::uint64_t>(x);
        else
            return std::bit_cast<std::uint32_t>(x);
    }

    std::uint64_t hashPair(const V3& wo, const V3& wi, std::uint64_t stream) const {
        return hashValues({seed_, stream, bits(wo.x), bits(wo.y), bits(wo.z), bits(wi.x),
                           bits(wi.y), bits(wi.z)});
    }

    static Float power(Float a, Float b) {
        const Float a2 = a * a, b2 = b * b;
        return a2 + b2 > Float(0) ? a2 / (a2 + b2) : Float(0);
    }

    // One walk of estimate(): its value and density estimates, added to `out`.
    void walk(const V3& wo, const V3& wi, TransportMode mode, Pcg32& rng, Estimate& out) const;

    CoatInterface<S> top_;
    std::unique_ptr<Bxdf<S>> base_;
    Medium medium_;
    int maxDepth_;
    int samples_;
    std::uint64_t seed_;
};

}  // namespace lamina

#include "lamina/bsdf/coated_walk.h"

namespace lamina {

LAMINA_EXTERN_BSDF_VARIANTS(CoatedBxdf)

/// `coated` (coated_reader.cpp): a dielectric coat over a base without transmission, with an
/// optional medium between them; evaluated by a random walk.
struct CoatedMaterial {
    double ior = 1.5;
    MicrofacetParams microfacet;  ///< the coat's roughness (0: smooth)
    std::shared_ptr<const MaterialDesc> base;
    double thickness = 0;  ///< optical thickness of the medium at normal incidence; 0: none
    ColorInput albedo{RgbInput(0.0)};  ///< single-scattering albedo of the medium
    double g = 0;                      ///< Henyey-Greenstein asymmetry
    int maxDepth = 0;  ///< the most events of a walk; 0: no cap (Russian roulette ends it)
    int samples = 1;
    /// Whether the base has a delta lobe (readCoated): a textured coat roughness then stays
    /// rough (texturedCoated), as a smooth coat over such a base is refused.
    bool baseHasDeltaLobe = false;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const CoatedMaterial& c, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    typename CoatedBxdf<S>::Medium medium;
    medium.thickness = Float(c.thickness);
    medium.albedo = b.context().reflectance(c.albedo);
    medium.g = Float(c.g);
    // A coated base gets a seed of its own: with an index-matched coat its walk would see
    // the same pairs as this one, and the same seed would replay this walk's numbers.
    const MaterialBuilder<S> baseBuilder(b.context(), hashValues({b.walkSeed(), 0x62617365ull}));
    return std::make_unique<CoatedBxdf<S>>(
        CoatInterface<S>(Float(c.ior), MaterialBuilder<S>::distribution(c.microfacet),
                         c.microfacet.g2),
        baseBuilder.build(*c.base), medium, c.maxDepth, c.samples, b.walkSeed());
}
LAMINA_MATERIAL_MODEL(CoatedMaterial)

}  // namespace lamina
