// A conductor: specular reflection only, smooth (a delta lobe) when alpha is below
// kSmoothAlpha and rough (microfacet) otherwise, with any Fresnel model, optionally with
// Kulla-Conty multiple-scattering compensation (multiscatter.h). Two-sided.
//
// With compensation, sampling picks the microfacet lobe or the cosine-sampled compensation
// lobe in proportion to estimates of their albedos at wo; weight = eval / pdf of the mixture.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/microfacet_reflection.h"
#include "lamina/bsdf/multiscatter.h"
#include "lamina/bsdf/polarised_fresnel.h"

namespace lamina {

template <SpectrumType S>
class ConductorBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    explicit ConductorBxdf(const MicrofacetReflectionLobe<S>& lobe,
                           std::optional<MultiscatterLobe<S>> multiscatter = std::nullopt)
        : lobe_(lobe), ms_(isSmooth() ? std::nullopt : std::move(multiscatter)) {}

    bool isSmooth() const { return lobe_.distribution().effectivelySmooth(); }
    const MicrofacetReflectionLobe<S>& lobe() const { return lobe_; }

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (isSmooth()) return S(Float(0));
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        S f = lobe_.eval(wo * s, wi * s);
        if (ms_) f += ms_->eval(wo * s, wi * s);
        return f;
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (isSmooth()) return Float(0);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        const V3 o = wo * s, i = wi * s;
        if (!ms_) return lobe_.pdf(o, i);
        const Float p = multiscatterProbability(o.z);
        return (Float(1) - p) * lobe_.pdf(o, i) + p * cosineHemispherePdf(i);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        if (isSmooth()) {
            const V3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample<S>{wi, lobe_.fresnel().evaluate(std::abs(wo.z)), Float(1),
                                 kLobeSpecularReflection, Float(1)};
        }
        if (!ms_) {
            const auto r = lobe_.sample(wo * s, u);
            if (!r) return std::nullopt;
            return BsdfSample<S>{r->wi * s, r->weight, r->pdf, kLobeGlossyReflection, Float(1)};
        }
        V3 wi;
        if (uc < multiscatterProbability(std::abs(wo.z))) {
            wi = squareToCosineHemisphere(u) * s;
        } else {
            const auto r = lobe_.sample(wo * s, u);
            if (!r) return std::nullopt;
            wi = r->wi * s;
        }
        const Float p = pdf(wo, wi);
        if (!(p > Float(0)) || !std::isfinite(p)) return std::nullopt;
        const S weight = eval(wo, wi, mode) / p;
        if (!weight.isFinite()) return std::nullopt;
        return BsdfSample<S>{wi, weight, p, kLobeGlossyReflection, Float(1)};
    }

    /// The microfacet lobe polarises as its Fresnel model does on each microfacet; the
    /// multiple-scattering compensation lobe is an ideal depolariser.
    MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode) const override {
        if (isSmooth()) return MuellerMatrix<S>();
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        MuellerMatrix<S> m = reflectionMueller(lobe_.eval(wo * s, wi * s), lobe_.fresnel(), wo, wi);
        if (ms_) m += depolarising(ms_->eval(wo * s, wi * s));
        return m;
    }

    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        if (!s.isSpecular()) return evalMueller(wo, s.wi, mode) / s.pdf;
        return reflectionMueller(s.weight, lobe_.fresnel(), wo, s.wi);
    }

    std::uint32_t flags() const override {
        return isSmooth() ? kLobeSpecularReflection : kLobeGlossyReflection;
    }

  private:
    // Share of the compensation lobe: its albedo against the single-scattering lobe's
    // (estimated by E(mu) times the mean Fresnel), with at least 5% each.
    Float multiscatterProbability(Float muO) const {
        const Float ms = ms_->albedo(muO).average();
        const Float ss = Float(ms_->table()(muO)) * lobe_.fresnel().evaluate(muO).average();
        const Float total = ms + ss;
        return total > Float(0) ? clamp(ms / total, Float(0.05), Float(0.95)) : Float(0.5);
    }

    MicrofacetReflectionLobe<S> lobe_;
    std::optional<MultiscatterLobe<S>> ms_;
};

}  // namespace lamina
