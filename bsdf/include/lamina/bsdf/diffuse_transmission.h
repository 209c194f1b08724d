// Lambertian reflection to the side of wo plus Lambertian transmission to the other side, as
// pbrt-v4's DiffuseTransmissionBxDF (Pharr, Jakob and Humphreys, pbrt-v4 source, bxdfs.h):
//   f(wo, wi) = reflectance / pi    (wi on wo's side)
//   f(wo, wi) = transmittance / pi  (wi on the other side).
// The albedo is reflectance + transmittance at every wo (at most 1 per channel for a surface
// that conserves energy). sample() picks reflection with probability
// p_r = max(reflectance) / (max(reflectance) + max(transmittance)) and cosine-samples the
// chosen side, so pdf(wo, wi) = p_side |cos theta_i| / pi exactly and the weight is
// reflectance / p_r or transmittance / (1 - p_r). No index of refraction: transmission does
// not scale radiance (eta = 1), and f is symmetric, so both transport modes agree.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/warp.h"

namespace lamina {

template <SpectrumType S>
class DiffuseTransmissionBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    DiffuseTransmissionBxdf(const S& reflectance, const S& transmittance)
        : reflectance_(reflectance), transmittance_(transmittance) {
        const Float r = reflectance.maxValue(), t = transmittance.maxValue();
        reflectProbability_ = r + t > Float(0) ? r / (r + t) : Float(0);
    }

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (wo.z == Float(0) || wi.z == Float(0)) return S(Float(0));
        const S& albedo = sameHemisphere(wo, wi) ? reflectance_ : transmittance_;
        return albedo * (kInvPi<Float> * std::abs(wi.z));
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (wo.z == Float(0) || wi.z == Float(0)) return Float(0);
        const Float side =
            sameHemisphere(wo, wi) ? reflectProbability_ : Float(1) - reflectProbability_;
        return side * std::abs(wi.z) * kInvPi<Float>;
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        V3 wi = squareToCosineHemisphere(u);
        if (!(wi.z > Float(0))) return std::nullopt;  // u on the disk's rim: wi at the horizon
        const bool reflect = uc < reflectProbability_;
        const Float side = reflect ? reflectProbability_ : Float(1) - reflectProbability_;
        if (!(side > Float(0))) return std::nullopt;
        // Reflection stays on wo's side, transmission goes to the other.
        if ((wo.z < Float(0)) == reflect) wi.z = -wi.z;
        const S& albedo = reflect ? reflectance_ : transmittance_;
        return BsdfSample<S>{wi, albedo / side, side * std::abs(wi.z) * kInvPi<Float>,
                             reflect ? kLobeDiffuseReflection : kLobeDiffuseTransmission, Float(1)};
    }

    std::uint32_t flags() const override {
        std::uint32_t f = kLobeNone;
        if (reflectProbability_ > Float(0)) f |= kLobeDiffuseReflection;
        if (reflectProbability_ < Float(1) && transmittance_.maxValue() > Float(0))
            f |= kLobeDiffuseTransmission;
        return f;
    }

  private:
    S reflectance_, transmittance_;
    Float reflectProbability_ = 0;
};

LAMINA_EXTERN_BSDF_VARIANTS(DiffuseTransmissionBxdf)

/// `diffuse_transmission`: Lambertian reflection and transmission (lobe_readers.cpp). Defaults
/// are pbrt-v4's.
struct DiffuseTransmissionMaterial {
    ColorInput reflectance{RgbInput(0.25)};
    ColorInput transmittance{RgbInput(0.25)};
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const DiffuseTransmissionMaterial& d,
                                    const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    const S r = b.context().reflectance(d.reflectance),
            t = b.context().reflectance(d.transmittance);
    if (r.maxValue() <= Float(0) && t.maxValue() <= Float(0))
        return std::make_unique<LayeredBxdf<S>>(typename LayeredBxdf<S>::Layers{});
    return std::make_unique<DiffuseTransmissionBxdf<S>>(r, t);
}
LAMINA_MATERIAL_MODEL(DiffuseTransmissionMaterial)

}  // namespace lamina
