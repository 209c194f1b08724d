// The specular interface of a layered material: a microfacet reflection lobe (GGX, Beckmann,
// Blinn-Phong) or the article's Phong lobe, behind one set of functions.
#pragma once

#include <variant>

#include "lamina/bsdf/microfacet_reflection.h"
#include "lamina/bsdf/phong.h"

namespace lamina {

template <SpectrumType S>
class SpecularLobe {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;
    using Sample = LobeSample<S>;

    SpecularLobe(const MicrofacetDistribution<Float>& d, const Fresnel<S>& f,
                 MicrofacetSampling sampling = MicrofacetSampling::VisibleNormals,
                 G2Form g2 = G2Form::HeightCorrelated)
        : lobe_(std::in_place_type<MicrofacetReflectionLobe<S>>, d, f, sampling, g2) {}
    explicit SpecularLobe(const PhongLobe<S>& phong) : lobe_(phong) {}

    S eval(const V3& wo, const V3& wi) const {
        return std::visit([&](const auto& l) { return l.eval(wo, wi); }, lobe_);
    }
    Float pdf(const V3& wo, const V3& wi) const {
        return std::visit([&](const auto& l) { return l.pdf(wo, wi); }, lobe_);
    }
    std::optional<Sample> sample(const V3& wo, const V2& u) const {
        return std::visit([&](const auto& l) { return l.sample(wo, u); }, lobe_);
    }
    const Fresnel<S>& fresnel() const {
        return std::visit([](const auto& l) -> const Fresnel<S>& { return l.fresnel(); }, lobe_);
    }
    /// F(wo.h) on the half vector of (wo, wi): the article's coupling.
    S fresnelAt(const V3& wo, const V3& wi) const {
        const auto m = MicrofacetReflectionLobe<S>::halfVector(wo, wi);
        return m ? fresnel().evaluate(glm::dot(wo, *m)) : fresnel().evaluate(Float(1));
    }
    /// A smooth microfacet interface is a delta lobe; Phong never is.
    bool isSmooth() const {
        const auto* m = std::get_if<MicrofacetReflectionLobe<S>>(&lobe_);
        return m && m->distribution().effectivelySmooth();
    }
    bool isPhong() const { return std::holds_alternative<PhongLobe<S>>(lobe_); }
    /// The microfacet lobe (nullptr for Phong).
    const MicrofacetReflectionLobe<S>* microfacet() const {
        return std::get_if<MicrofacetReflectionLobe<S>>(&lobe_);
    }

  private:
    std::variant<MicrofacetReflectionLobe<S>, PhongLobe<S>> lobe_;
};

}  // namespace lamina
