// The article's Phong lobe (section 3.2; Phong 1975 with the normalisation that makes it
// energy-conserving for path tracing, Lafortune and Willems 1994):
//   f(wo, wi) |cos theta_i| = rho (s + 1) / (2 pi) max(0, R.wi)^s cos theta_i,
// R = wo mirrored about the normal (so R.wi = reflect(-wi).wo: the lobe is reciprocal). The
// exponent comes from the microfacet alpha by Walter et al. 2007's conversion
// s = 2 / alpha^2 - 2 (section 5.2), alpha^2 clamped to [2e-4, 0.9999] as in the article's
// code. Sampled by the cosine-power lobe around R, pdf (s + 1) / (2 pi) (R.wi)^s; directions
// below the surface are rejected, so weight = rho cos theta_i (the article's F0 * NdotL).
// The lobe has no angular Fresnel of its own; `fresnel` is the model a layered material uses
// to weight its base (the article weights its diffuse by 1 - F(wi.h) with Phong too).
#pragma once

#include <optional>

#include "lamina/bsdf/bsdf_sample.h"
#include "lamina/bsdf/fresnel.h"
#include "lamina/core/frame.h"

namespace lamina {

template <SpectrumType S>
class PhongLobe {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;

    using Sample = LobeSample<S>;

    static Float shininessFromAlpha(Float alpha) {
        return Float(2) / clamp(alpha * alpha, Float(2e-4), Float(0.9999)) - Float(2);
    }

    PhongLobe(const S& reflectance, Float shininess, const Fresnel<S>& couplingFresnel)
        : rho_(reflectance), s_(shininess), fresnel_(couplingFresnel) {}

    Float shininess() const { return s_; }
    const Fresnel<S>& fresnel() const { return fresnel_; }

    S eval(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return S(Float(0));
        return rho_ * (lobe(wo, wi) * wi.z);
    }

    Float pdf(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return Float(0);
        return lobe(wo, wi);
    }

    std::optional<Sample> sample(const V3& wo, const V2& u) const {
        if (!(wo.z > Float(0))) return std::nullopt;
        const Float cosA = std::pow(u.x, Float(1) / (s_ + Float(1)));
        const Float sinA = safeSqrt(Float(1) - cosA * cosA);
        const Float phi = Float(2) * kPi<Float> * u.y;
        const V3 wi = Frame<Float>::fromNormal(mirror(wo))
                          .toWorld(V3(sinA * std::cos(phi), sinA * std::sin(phi), cosA));
        if (!(wi.z > Float(0))) return std::nullopt;
        const Float p = lobe(wo, wi);
        if (!(p > Float(0)) || !std::isfinite(p)) return std::nullopt;
        return Sample{wi, rho_ * wi.z, p};
    }

  private:
    static V3 mirror(const V3& w) { return V3(-w.x, -w.y, w.z); }

    // (s + 1) / (2 pi) max(0, R.wi)^s: the normalised cosine-power lobe around R.
    Float lobe(const V3& wo, const V3& wi) const {
        const Float c = glm::dot(mirror(wo), wi);
        if (!(c > Float(0))) return Float(0);
        return (s_ + Float(1)) / (Float(2) * kPi<Float>)*std::pow(std::min(c, Float(1)), s_);
    }

    S rho_;
    Float s_;
    Fresnel<S> fresnel_;
};

}  // namespace lamina

// The `phong` material (lobe_readers.cpp): the lobe alone, as the interface of a LayeredBxdf,
// whose header includes this one: it is declared here and included at the end.
#include "lamina/bsdf/material_builder.h"

namespace lamina {

template <SpectrumType S>
class LayeredBxdf;

/// `phong`: the article's Phong lobe alone.
struct PhongMaterial {
    ColorInput reflectance{RgbInput(0.5)};
    double shininess = 0;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const PhongMaterial& p, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    typename LayeredBxdf<S>::Layers layers;
    const S rho = b.context().reflectance(p.reflectance);
    layers.interface.emplace(PhongLobe<S>(rho, Float(p.shininess), Fresnel<S>::schlick(rho)));
    return std::make_unique<LayeredBxdf<S>>(std::move(layers));
}
LAMINA_MATERIAL_MODEL(PhongMaterial)

}  // namespace lamina

#include "lamina/bsdf/layered.h"
