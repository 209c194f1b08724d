// The BSDF interface. "The article" throughout bsdf/ is Boksansky, "Crash Course in BRDF
// Implementation", 2021; this interface has its four functions (eval, pdf, sample; sample is
// the article's evalIndirect). Directions are in the local shading frame (z = shading
// normal), both pointing away from the surface: wo towards the viewer, wi towards the light.
#pragma once

#include <optional>
#include <string>

#include "lamina/bsdf/bsdf_sample.h"
#include "lamina/bsdf/bsdf_variants.h"
#include "lamina/core/mueller_matrix.h"

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

    /// The polarised mode's eval (docs/polarisation.md): the Mueller matrix per channel that
    /// maps the Stokes vector of light arriving along -wi to that of the light leaving along wo
    /// (in Radiance mode; the path integrator is the only one the polarised mode runs), each in
    /// the canonical frame of its local direction (stokesAxis). Its [0][0] is eval(). A BSDF
    /// that does not override it is an ideal depolariser.
    virtual MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode mode) const {
        return depolarising(eval(wo, wi, mode));
    }

    /// The Mueller weight of a sample sample() returned: for a delta lobe the lobe's matrix
    /// over its probability, whose [0][0] is the sample's weight; otherwise evalMueller / pdf.
    virtual MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                           TransportMode mode) const {
        if (s.isSpecular()) return depolarising(s.weight);
        return evalMueller(wo, s.wi, mode) / s.pdf;
    }

    /// Whether sample() reads `uc`. A BSDF of one lobe (DiffuseBxdf, every model) does not, and
    /// the integrators then skip the sampler's dimension for it rather than compute a number
    /// nobody reads (scatter.h); every other number of the path is the same either way.
    virtual bool usesLobeChoice() const { return true; }
};

}  // namespace lamina
