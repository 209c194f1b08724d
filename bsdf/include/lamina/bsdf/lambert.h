// Lambertian diffuse reflection (article section 3.1): f = reflectance / pi, cosine-weighted
// sampling, so weight = reflectance exactly. Two-sided: mirrored to the side of wo.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/warp.h"

namespace lamina {

template <SpectrumType S>
class LambertBxdf final : public Bxdf<S> {
public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    explicit LambertBxdf(const S& reflectance) : reflectance_(reflectance) {}

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (!sameHemisphere(wo, wi)) return S(0);
        return reflectance_ * (kInvPi<Float> * std::abs(wi.z));
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        return sameHemisphere(wo, wi) ? std::abs(wi.z) * kInvPi<Float> : Float(0);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float, const V2& u,
                                        TransportMode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        V3 wi = squareToCosineHemisphere(u);
        if (!(wi.z > Float(0))) return std::nullopt;  // u on the disk's rim: wi at the horizon
        if (wo.z < Float(0)) wi.z = -wi.z;
        return BsdfSample<S>{wi, reflectance_, std::abs(wi.z) * kInvPi<Float>,
                             kLobeDiffuseReflection, Float(1)};
    }

    std::uint32_t flags() const override { return kLobeDiffuseReflection; }

    const S& reflectance() const { return reflectance_; }

private:
    S reflectance_;
};

}  // namespace lamina
