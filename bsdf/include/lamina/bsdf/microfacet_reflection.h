// Rough specular reflection from a microfacet surface (the article, section 4; Walter et al.
// 2007 eq. 20 with the cosine built in):
//   f(wo, wi) |cos theta_i| = F(wo.m) D(m) G2(wo, wi) / (4 |cos theta_o|),  m = the half vector.
// This lobe works in the upper hemisphere (wo.z > 0, wi.z > 0); the BSDFs that use it mirror
// directions to that side. The distribution carries the sampling strategy.
#pragma once

#include <optional>

#include "lamina/bsdf/bsdf_sample.h"
#include "lamina/bsdf/bsdf_variants.h"
#include "lamina/bsdf/fresnel.h"
#include "lamina/bsdf/microfacet_distribution.h"

namespace lamina {

template <SpectrumType S>
class MicrofacetReflectionLobe {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;
    using Distribution = MicrofacetDistribution<Float>;

    using Sample = LobeSample<S>;

    MicrofacetReflectionLobe(const Distribution& d, const Fresnel<S>& f,
                             MicrofacetSampling sampling = MicrofacetSampling::VisibleNormals,
                             G2Form g2 = G2Form::HeightCorrelated)
        : distribution_(d.sampledBy(sampling)), fresnel_(f), g2_(g2) {}

    const Distribution& distribution() const { return distribution_; }
    const Fresnel<S>& fresnel() const { return fresnel_; }

    /// The half vector of a reflection pair, or nullopt when it is undefined (wo = -wi).
    static std::optional<V3> halfVector(const V3& wo, const V3& wi) {
        const V3 m = safeNormalize(wo + wi);
        if (m == V3(Float(0))) return std::nullopt;
        return m.z < Float(0) ? -m : m;
    }

    /// F(wo.m) for the half vector of (wo, wi): what the coupling of a layered material uses.
    S fresnelAt(const V3& wo, const V3& wi) const {
        const auto m = halfVector(wo, wi);
        return m ? fresnel_.evaluate(glm::dot(wo, *m)) : fresnel_.evaluate(Float(1));
    }

    S eval(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return S(Float(0));
        const auto m = halfVector(wo, wi);
        if (!m) return S(Float(0));
        return fresnel_.evaluate(glm::dot(wo, *m)) * evalWithoutFresnel(wo, wi);
    }

    /// D(m) G2(wo, wi) / (4 cos_o): eval() without its Fresnel factor, for a layer that weights
    /// the microfacets by the Fresnel of another side (a layered interface seen from inside).
    Float evalWithoutFresnel(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return Float(0);
        const auto m = halfVector(wo, wi);
        if (!m) return Float(0);
        return distribution_.D(*m) * distribution_.G2(wo, wi, g2_) / (Float(4) * wo.z);
    }

    Float pdf(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return Float(0);
        const auto m = halfVector(wo, wi);
        if (!m) return Float(0);
        return distribution_.normalPdf(wo, *m) / (Float(4) * std::abs(glm::dot(wo, *m)));
    }

    std::optional<Sample> sample(const V3& wo, const V2& u) const {
        if (!(wo.z > Float(0))) return std::nullopt;
        const V3 m = distribution_.sampleNormal(wo, u);
        const Float wom = glm::dot(wo, m);
        if (!(wom > Float(0))) return std::nullopt;
        const V3 wi = reflect(wo, m);
        if (!(wi.z > Float(0))) return std::nullopt;
        const Float p = distribution_.normalPdf(wo, m) / (Float(4) * wom);
        if (!(p > Float(0)) || !std::isfinite(p)) return std::nullopt;
        const S f = fresnel_.evaluate(wom);
        const std::optional<Float> cancelled = distribution_.reflectionWeight(wo, wi, m, g2_);
        return Sample{wi, cancelled ? f * *cancelled : eval(wo, wi) / p, p};
    }

  private:
    Distribution distribution_;
    Fresnel<S> fresnel_;
    G2Form g2_;
};

LAMINA_EXTERN_BSDF_VARIANTS(MicrofacetReflectionLobe)

}  // namespace lamina
