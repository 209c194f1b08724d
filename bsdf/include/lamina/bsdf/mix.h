// `mix`: a weighted blend of two BSDFs, f = (1 - w) f_a + w f_b. Sampling picks a by
// probability 1 - w and b by w, so the mixture pdf is (1 - w) p_a + w p_b and the weight of a
// non-delta sample is the blend's eval / pdf; a delta sample keeps its own weight (its
// selection probability cancels the blend weight).
#pragma once

#include <memory>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"

namespace lamina {

template <SpectrumType S>
class MixBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    MixBxdf(std::unique_ptr<Bxdf<S>> a, std::unique_ptr<Bxdf<S>> b, Float weight)
        : a_(std::move(a)), b_(std::move(b)), w_(weight) {}

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        return a_->eval(wo, wi, mode) * (Float(1) - w_) + b_->eval(wo, wi, mode) * w_;
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        return (Float(1) - w_) * a_->pdf(wo, wi) + w_ * b_->pdf(wo, wi);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        const bool pickB = uc >= Float(1) - w_;
        // Reuse uc for the chosen component: rescaled to [0, 1).
        const Float remapped = pickB ? (uc - (Float(1) - w_)) / w_ : uc / (Float(1) - w_);
        const Float uc2 = std::min(remapped, kOneMinusEpsilon<Float>);
        auto s = (pickB ? b_ : a_)->sample(wo, uc2, u, mode);
        if (!s) return std::nullopt;
        if (s->isSpecular()) {
            s->pdf *= pickB ? w_ : Float(1) - w_;
            return s;
        }
        const Float p = pdf(wo, s->wi);
        if (!(p > Float(0))) return std::nullopt;
        s->weight = eval(wo, s->wi, mode) / p;
        s->pdf = p;
        if (!s->weight.isFinite()) return std::nullopt;
        return s;
    }

    std::uint32_t flags() const override { return a_->flags() | b_->flags(); }

  private:
    std::unique_ptr<Bxdf<S>> a_, b_;
    Float w_;
};

LAMINA_EXTERN_BSDF_VARIANTS(MixBxdf)

/// `mix` (mix_reader.cpp): (1 - weight) a + weight b.
struct MixMaterial {
    std::shared_ptr<const MaterialDesc> a, b;
    double weight = 0.5;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const MixMaterial& m, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    return std::make_unique<MixBxdf<S>>(b.build(*m.a), b.build(*m.b), Float(m.weight));
}
LAMINA_MATERIAL_MODEL(MixMaterial)

}  // namespace lamina
