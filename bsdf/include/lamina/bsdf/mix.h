// `mix`: a weighted blend of two BSDFs, f = (1 - w) f_a + w f_b. Sampling picks a by
// probability 1 - w and b by w, so the mixture pdf is (1 - w) p_a + w p_b and the weight of a
// non-delta sample is the blend's eval / pdf; a delta sample keeps its own weight (its
// selection probability cancels the blend weight).
//
// Polarised, the blend is the same sum of the two materials' Mueller matrices, in the same
// canonical frames (docs/polarisation.md). A delta sample's matrix is its own material's: the
// sample records which material drew it in BsdfSample::component, each mix shifting the bits of
// the mixes inside it up by one and putting its own choice in bit 0, so sampleMueller reads its
// bit and hands the sample on with the rest. The 16 bits hold kMaxMixNesting mixes inside each
// other; the reader refuses more.
#pragma once

#include <limits>
#include <memory>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"

namespace lamina {

/// How many mixes may nest inside each other: one bit of BsdfSample::component each.
inline constexpr int kMaxMixNesting = 16;
static_assert(kMaxMixNesting ==
              std::numeric_limits<decltype(BsdfSample<Rgb<float>>::component)>::digits);

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
            s->component = std::uint16_t((s->component << 1) | (pickB ? 1u : 0u));
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

    /// The blend of the two materials' matrices; [0][0] is eval() to the last bit (the same
    /// sum of the same products).
    MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode mode) const override {
        return a_->evalMueller(wo, wi, mode) * (Float(1) - w_) + b_->evalMueller(wo, wi, mode) * w_;
    }

    /// A delta sample goes back to the material that drew it (bit 0 of its component), with
    /// that material's own probability of it and the bits of the mixes inside it.
    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        if (!s.isSpecular()) return evalMueller(wo, s.wi, mode) / s.pdf;
        const bool pickB = (s.component & 1u) != 0;
        BsdfSample<S> own = s;
        own.pdf = s.pdf / (pickB ? w_ : Float(1) - w_);
        own.component = std::uint16_t(s.component >> 1);
        return (pickB ? b_ : a_)->sampleMueller(wo, own, mode);
    }

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
