// A conductor: specular reflection only, smooth (a delta lobe) when alpha is below
// kSmoothAlpha and rough (microfacet) otherwise, with any Fresnel model. Two-sided.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/microfacet_reflection.h"

namespace lamina {

template <SpectrumType S>
class ConductorBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    explicit ConductorBxdf(const MicrofacetReflectionLobe<S>& lobe) : lobe_(lobe) {}

    bool isSmooth() const { return lobe_.distribution().effectivelySmooth(); }

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (isSmooth()) return S(Float(0));
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        return lobe_.eval(wo * s, wi * s);
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (isSmooth()) return Float(0);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        return lobe_.pdf(wo * s, wi * s);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float, const V2& u,
                                        TransportMode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        if (isSmooth()) {
            const V3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample<S>{wi, lobe_.fresnel().evaluate(std::abs(wo.z)), Float(1),
                                 kLobeSpecularReflection, Float(1)};
        }
        const auto r = lobe_.sample(wo * s, u);
        if (!r) return std::nullopt;
        return BsdfSample<S>{r->wi * s, r->weight, r->pdf, kLobeGlossyReflection, Float(1)};
    }

    std::uint32_t flags() const override {
        return isSmooth() ? kLobeSpecularReflection : kLobeGlossyReflection;
    }

  private:
    MicrofacetReflectionLobe<S> lobe_;
};

}  // namespace lamina
