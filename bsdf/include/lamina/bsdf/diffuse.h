// Diffuse reflection models (the article, sections 3.1-3.5). All are two-sided (mirrored to the
// side of wo) and cosine-sampled, so weight = eval / pdf = reflectance * shape(wo, wi), where
// f(wo, wi) = reflectance / pi * shape(wo, wi):
//   Lambert      shape = 1.
//   Oren-Nayar   the "qualitative" model of Oren and Nayar 1994 (eq. 30, as in the article):
//                A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta), with
//                A = 1 - 0.5 s^2 / (s^2 + 0.33), B = 0.45 s^2 / (s^2 + 0.09), and the slope
//                deviation s = 0.7071 atan(alpha_microfacet) (Lagarde and de Rousiers 2014,
//                "Moving Frostbite to PBR", appendix B). Reciprocal.
//   Burley       Disney diffuse (Burley 2012, "Physically-Based Shading at Disney", eq. 4):
//                (1 + (F_D90 - 1)(1 - cos_l)^5)(1 + (F_D90 - 1)(1 - cos_v)^5),
//                F_D90 = 0.5 + 2 roughness cos^2(theta_d). Reciprocal; not energy
//                conserving (albedo above 1 at grazing angles for rough white surfaces).
//   Frostbite    Lagarde and de Rousiers 2014, listing 1: Burley's form with
//                F_D90 = 0.5 roughness + 2 roughness cos^2(theta_d), scaled by
//                lerp(1, 1/1.51, roughness), renormalised to combine with GGX specular.
// `roughness` is the perceptual roughness (alpha = roughness^2).
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/name_table.h"
#include "lamina/core/warp.h"

namespace lamina {

enum class DiffuseModel { Lambert, OrenNayar, Burley, Frostbite };
inline constexpr NameTable kDiffuseModelNames{std::array{
    NameEntry{DiffuseModel::Lambert, "lambert"}, NameEntry{DiffuseModel::OrenNayar, "oren_nayar"},
    NameEntry{DiffuseModel::Burley, "burley"}, NameEntry{DiffuseModel::Frostbite, "frostbite"}}};

template <SpectrumType S>
class DiffuseBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    explicit DiffuseBxdf(const S& reflectance, DiffuseModel model = DiffuseModel::Lambert,
                         Float roughness = Float(0))
        : reflectance_(reflectance), model_(model), roughness_(roughness) {
        const Float s = Float(0.7071067811865476) * std::atan(roughness * roughness);
        const Float s2 = s * s;
        orenNayarA_ = Float(1) - Float(0.5) * s2 / (s2 + Float(0.33));
        orenNayarB_ = Float(0.45) * s2 / (s2 + Float(0.09));
    }

    const S& reflectance() const { return reflectance_; }
    DiffuseModel model() const { return model_; }

    /// The scalar factor of the model: f = reflectance / pi * shape (wo, wi in one hemisphere).
    Float shape(const V3& wo, const V3& wi) const {
        const Float cosO = std::abs(wo.z), cosI = std::abs(wi.z);
        switch (model_) {
            case DiffuseModel::Lambert:
                return Float(1);
            case DiffuseModel::OrenNayar: {
                const Float sinO = sinTheta(wo), sinI = sinTheta(wi);
                Float cosDeltaPhi = Float(0);
                if (sinO > Float(1e-6) && sinI > Float(1e-6))
                    cosDeltaPhi =
                        clamp((wo.x * wi.x + wo.y * wi.y) / (sinO * sinI), Float(-1), Float(1));
                // alpha = max(theta_i, theta_o), beta = min(...): sin(alpha) tan(beta).
                const Float sinAlphaTanBeta =
                    cosI > cosO ? sinO * sinI / cosI : sinI * sinO / std::max(cosO, Float(1e-30));
                return orenNayarA_ +
                       orenNayarB_ * std::max(Float(0), cosDeltaPhi) * sinAlphaTanBeta;
            }
            case DiffuseModel::Burley:
            case DiffuseModel::Frostbite: {
                // cos^2(theta_d) = (wi.h)^2 = (1 + wo.wi) / 2 for the half vector h.
                const Float cos2D =
                    clamp(Float(0.5) * (Float(1) + glm::dot(wo, wi)), Float(0), Float(1));
                const bool frostbite = model_ == DiffuseModel::Frostbite;
                const Float fd90 = (frostbite ? Float(0.5) * roughness_ : Float(0.5)) +
                                   Float(2) * roughness_ * cos2D;
                const Float scale =
                    frostbite ? lerp(roughness_, Float(1), Float(1) / Float(1.51)) : Float(1);
                // 1 + (F_D90 - 1)(1 - c)^5, written as (1 - (1 - c)^5) + F_D90 (1 - c)^5 so
                // that a small F_D90 at grazing angles does not cancel catastrophically.
                auto term = [fd90](Float c) {
                    return oneMinusPow5OfComplement(c) + fd90 * pow5(Float(1) - c);
                };
                return term(cosI) * term(cosO) * scale;
            }
        }
        return Float(1);
    }

    S eval(const V3& wo, const V3& wi, TransportMode) const override {
        if (!sameHemisphere(wo, wi)) return S(Float(0));
        return reflectance_ * (kInvPi<Float> * std::abs(wi.z) * shape(wo, wi));
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
        return BsdfSample<S>{wi, reflectance_ * shape(wo, wi), std::abs(wi.z) * kInvPi<Float>,
                             kLobeDiffuseReflection, Float(1)};
    }

    std::uint32_t flags() const override { return kLobeDiffuseReflection; }
    bool usesLobeChoice() const override { return false; }

  private:
    S reflectance_;
    DiffuseModel model_;
    Float roughness_;
    Float orenNayarA_ = 1, orenNayarB_ = 0;
};

}  // namespace lamina

// The diffuse material types (lobe_readers.cpp). A black one builds an empty LayeredBxdf, whose
// header includes this one: it is declared here and included at the end.
#include "lamina/bsdf/material_builder.h"

namespace lamina {

template <SpectrumType S>
class LayeredBxdf;

/// `lambert`, `oren_nayar`, `burley`, `frostbite`.
struct DiffuseMaterial {
    DiffuseModel model = DiffuseModel::Lambert;
    ColorInput reflectance{RgbInput(0.5)};
    double roughness = 0;  ///< perceptual
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const DiffuseMaterial& d, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    // A black diffuse surface (an emitter's back, say) has no lobe at all.
    if (d.reflectance.rgb.maxValue() <= 0.0 && !d.reflectance.spectrum)
        return std::make_unique<LayeredBxdf<S>>(typename LayeredBxdf<S>::Layers{});
    return std::make_unique<DiffuseBxdf<S>>(b.context().reflectance(d.reflectance), d.model,
                                            Float(d.roughness));
}
LAMINA_MATERIAL_MODEL(DiffuseMaterial)
LAMINA_EXTERN_BSDF_VARIANTS(DiffuseBxdf)

}  // namespace lamina

#include "lamina/bsdf/layered.h"
