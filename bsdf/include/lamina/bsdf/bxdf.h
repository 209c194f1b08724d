// The BSDF interface. "The article" throughout bsdf/ is Boksansky, "Crash Course in BRDF
// Implementation", 2021; this interface has its four functions (eval, pdf, sample; sample is
// the article's evalIndirect). Directions are in the local shading frame (z = shading
// normal), both pointing away from the surface: wo towards the viewer, wi towards the light.
#pragma once

#include <optional>
#include <string>

#include "lamina/bsdf/bsdf_sample.h"

namespace lamina {

template <SpectrumType S>
class Bxdf {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;

    virtual ~Bxdf() = default;

    /// f(wo, wi) * |cos theta_i| (the cosine is built in, as in the article). Zero for delta
    /// lobes.
    virtual S eval(const V3& wo, const V3& wi, TransportMode mode) const = 0;

    /// Solid-angle density with which sample(wo) returns wi, summed over the non-delta lobes
    /// with their selection probabilities. Reversed (pdf(wi, wo)) for BDPT.
    virtual Float pdf(const V3& wo, const V3& wi) const = 0;

    /// Draws wi. `uc` chooses a lobe, `u` the direction within it. nullopt when the sample
    /// is absorbed (no direction or zero weight).
    virtual std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                                TransportMode mode) const = 0;

    /// The union of the flags of the lobes this BSDF has.
    virtual std::uint32_t flags() const = 0;

    /// Whether sample() reads `uc`. A BSDF of one lobe (DiffuseBxdf, every model) does not, and
    /// the integrators then skip the sampler's dimension for it rather than compute a number
    /// nobody reads (scatter.h); every other number of the path is the same either way.
    virtual bool usesLobeChoice() const { return true; }
};

}  // namespace lamina
