// The layered stack (the article, section 5, generalised): a specular interface (microfacet or
// the article's Phong lobe) over a base of diffuse reflection and/or rough dielectric
// transmission, split by `transmission` (the article's diffuse probability):
//
//   f = f_spec + (1 - t) W(wo, wi) f_diffuse + t (1 - F(wo.m_t)) f_btdf
//
// f_spec is the interface's microfacet reflection (delta when smooth); W is the coupling:
//   fresnel  W = 1 - F(wi.h) on the half vector h of (wo, wi), the same h as f_spec, in eval
//            and in sampling alike (the article's code sample samples a different h for the
//            diffuse weight, which breaks weight == eval/pdf; lamina does not);
//   sum      W = 1 (the article's combination for Frostbite's diffuse, which is normalised
//            for GGX specular);
//   albedo   W = (1 - E(mu_o)) (1 - E(mu_i)) / (1 - E_avg) with E the interface's directional
//            albedo (Kelemen and Szirmay-Kalos 2001; Kulla and Conty 2017): reciprocal, and
//            a white base under any interface reflects exactly what the interface transmits.
// The base may instead be a rough conductor under the interface (refracted_conductor.h: the
// conductor evaluated at wo and wi refracted into the coat, Weidlich and Wilkie 2007), which adds
//
//   W_c(wo, wi) f_conductor(wo', wi') / eta^2
//
// with its own coupling W_c, the transmittance of the way in and the way out:
//   fresnel  W_c = 1 - F(wi.h), as for the diffuse base (the article's weighting, applied once);
//   sum      W_c = 1;
//   albedo   W_c = (1 - E(mu_o)) (1 - E(mu_i)): what the rough interface lets through on the
//            way in and on the way out, E its directional albedo (for a smooth interface
//            E = F and this is the exact single-pass transmittance of Weidlich and Wilkie).
//            It is reciprocal, and with the conductor's albedo <= 1 the stack reflects at most
//            E(mu_o) + (1 - E(mu_o)) = 1. The diffuse base's 1 / (1 - E_avg) is left out: it
//            returns the energy the interface reflects as a Lambertian base would spread it, so
//            that a white Lambertian base reflects exactly what the interface transmits; a
//            conductor keeps light near its mirror direction, and with that factor a white
//            mirror under a smooth coat of index 1.5 would reflect 1.05 at normal incidence
//            ((1 - 0.04)^2 / (1 - 0.09) + 0.04).
// The interface may carry Kulla-Conty multiple-scattering compensation (multiscatter.h).
// f_btdf is Walter's BTDF without its Fresnel factor, weighted by (1 - F) of the interface's
// own Fresnel model on the refraction microfacet normal m_t, so reflection and transmission
// split each microfacet's energy exactly once (never twice: Mitsuba 3 issue 465). A Fresnel
// approximation seen from inside is evaluated at the angle outside (Snell's law), and total
// internal reflection gives F = 1. With transmission, wo below the surface is inside the
// material, and the interface's microfacet reflection there is weighted by that same Fresnel
// seen from inside, so that what it reflects and what it transmits add to 1 (with the outside
// Fresnel, light past the critical angle was neither transmitted nor reflected); with
// transmission weight 1 and the exact dielectric Fresnel the stack is Walter et al.'s rough
// dielectric from both sides. Without transmission a pair below the surface is the mirror
// image of the pair above (a two-sided opaque material).
//
// Sampling picks a lobe with probabilities estimated from wo (specular ~ F(cos_o), cosine
// lobes (diffuse and multiple-scattering compensation) ~ their albedos, transmission ~
// t (1 - F), the conductor base ~ its Fresnel at wo' times its coupling at wo; 10% spread evenly
// so no lobe is starved), then weight = eval / pdf of the whole mixture.
//
// Polarised (docs/polarisation.md), the interface's reflection, smooth or rough, polarises by
// the Fresnel amplitudes of its model on each microfacet (an F0-only model by the dielectric
// of the same F0, polarised_fresnel.h), the same from either side as its value is; every other
// term (the base, diffuse or conductor, the transmission through the interface, the
// multiple-scattering compensation) is an ideal depolariser: light that has crossed the
// interface twice or scattered in the base is modelled as having lost its polarisation. The
// article's Phong lobe has no Fresnel event of its own (its Fresnel model only weights the
// base) and depolarises too.
#pragma once

#include <array>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/microfacet_reflection.h"
#include "lamina/bsdf/multiscatter.h"
#include "lamina/bsdf/polarised_fresnel.h"
#include "lamina/bsdf/refracted_conductor.h"
#include "lamina/bsdf/specular_lobe.h"
#include "lamina/core/name_table.h"

namespace lamina {

enum class LayerCoupling { Fresnel, Sum, Albedo };
inline constexpr NameTable kLayerCouplingNames{
    std::array{NameEntry{LayerCoupling::Fresnel, "fresnel"}, NameEntry{LayerCoupling::Sum, "sum"},
               NameEntry{LayerCoupling::Albedo, "albedo"}}};

template <SpectrumType S>
class LayeredBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    struct Layers {
        std::optional<SpecularLobe<S>> interface;  ///< none: no specular layer
        std::optional<DiffuseBxdf<S>> diffuse;
        std::optional<DielectricBxdf<S>> transmission;  ///< geometry of the transmitted lobe
        Float transmissionWeight = 0;                   ///< t in [0, 1]
        LayerCoupling coupling = LayerCoupling::Fresnel;
        /// Albedo coupling: the interface's directional albedo (with compensation if any).
        std::shared_ptr<const AlbedoTable> interfaceAlbedo;
        std::optional<MultiscatterLobe<S>> interfaceMultiscatter;
        /// A rough conductor under the interface (with or instead of the diffuse base).
        std::optional<RefractedConductorLobe<S>> conductorBase;
    };

    explicit LayeredBxdf(Layers layers) : l_(std::move(layers)) {
        if (!l_.interface || interfaceSmooth()) l_.interfaceMultiscatter.reset();
        if (l_.coupling == LayerCoupling::Albedo && !l_.interfaceAlbedo)
            l_.coupling = LayerCoupling::Fresnel;
        if (!l_.transmission) l_.transmissionWeight = Float(0);
        if (l_.transmissionWeight <= Float(0)) l_.transmission.reset();
        if (l_.transmissionWeight >= Float(1)) l_.diffuse.reset();
    }

    const Layers& layers() const { return l_; }

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        if (wo.z == Float(0) || wi.z == Float(0)) return S(Float(0));
        if (!sameHemisphere(wo, wi)) return evalTransmission(wo, wi, mode);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        return evalReflection(wo * s, wi * s, mode, reflectsInside(wo));
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (wo.z == Float(0) || wi.z == Float(0)) return Float(0);
        const auto p = lobeProbabilities(wo);
        if (!sameHemisphere(wo, wi))
            return l_.transmission ? p[2] * l_.transmission->refractionPdf(wo, wi) : Float(0);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        const V3 o = wo * s, i = wi * s;
        Float result = Float(0);
        if (l_.interface && !interfaceSmooth()) result += p[0] * l_.interface->pdf(o, i);
        if (hasCosineLobe()) result += p[1] * cosineHemispherePdf(i);
        if (l_.conductorBase) result += p[3] * l_.conductorBase->pdf(o, i);
        return result;
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const auto p = lobeProbabilities(wo);
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        V3 wi;
        if (uc < p[0]) {  // specular interface
            if (interfaceSmooth()) {
                const S f = reflectsInside(wo) ? insideFresnel(wo, V3(0, 0, 1))
                                               : l_.interface->fresnel().evaluate(std::abs(wo.z));
                return BsdfSample<S>{V3(-wo.x, -wo.y, wo.z), f / p[0], p[0],
                                     kLobeSpecularReflection, Float(1)};
            }
            const auto r = l_.interface->sample(wo * s, u);
            if (!r) return std::nullopt;
            wi = r->wi * s;
        } else if (uc < p[0] + p[1]) {  // diffuse base and compensation: cosine-distributed
            wi = squareToCosineHemisphere(u) * s;
            if (wi.z == Float(0)) return std::nullopt;
        } else if (l_.conductorBase && uc >= p[0] + p[1] + p[2]) {  // conductor base
            const Float ub = std::min((uc - (p[0] + p[1] + p[2])) / p[3], kOneMinusEpsilon<Float>);
            const auto r = l_.conductorBase->sample(wo * s, ub, u, mode);
            if (!r) return std::nullopt;
            wi = *r * s;
        } else {  // transmission
            if (!l_.transmission) return std::nullopt;
            const auto t = l_.transmission->sampleRefraction(wo, u);
            if (!t) return std::nullopt;
            if (l_.transmission->isSmooth()) {
                const S weight =
                    transmissionFresnelFactor(wo, V3(0, 0, 1)) * (l_.transmissionWeight / p[2]) *
                    (mode == TransportMode::Radiance ? Float(1) / sqr(t->second) : Float(1));
                return BsdfSample<S>{t->first, weight, p[2], kLobeSpecularTransmission, t->second};
            }
            wi = t->first;
        }
        const Float pdfValue = pdf(wo, wi);
        if (!(pdfValue > Float(0)) || !std::isfinite(pdfValue)) return std::nullopt;
        const S weight = eval(wo, wi, mode) / pdfValue;
        if (!weight.isFinite()) return std::nullopt;
        const bool transmitted = !sameHemisphere(wo, wi);
        std::uint32_t flags;
        Float eta = Float(1);
        if (transmitted) {
            flags = kLobeGlossyTransmission;
            eta = wo.z > Float(0) ? l_.transmission->eta() : Float(1) / l_.transmission->eta();
        } else {
            flags = uc < p[0] || uc >= p[0] + p[1] ? kLobeGlossyReflection : kLobeDiffuseReflection;
        }
        return BsdfSample<S>{wi, weight, pdfValue, flags, eta};
    }

    /// The interface's reflection polarised, every other term depolarising (the top of this
    /// file); [0][0] is eval() to the last bit, its terms added in the same order.
    MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode mode) const override {
        if (wo.z == Float(0) || wi.z == Float(0)) return MuellerMatrix<S>();
        if (!sameHemisphere(wo, wi)) return depolarising(evalTransmission(wo, wi, mode));
        const Float s = wo.z < Float(0) ? Float(-1) : Float(1);
        MuellerMatrix<S> m;
        reflectionTerms(wo * s, wi * s, mode, reflectsInside(wo),
                        [&](const S& term, bool interface) {
                            m += interface ? interfaceMueller(term, wo, wi) : depolarising(term);
                        });
        return m;
    }

    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        if (!s.isSpecular()) return evalMueller(wo, s.wi, mode) / s.pdf;
        if (s.isTransmission()) return depolarising(s.weight);
        return interfaceMueller(s.weight, wo, s.wi);
    }

    std::uint32_t flags() const override {
        std::uint32_t f = kLobeNone;
        if (l_.interface) f |= interfaceSmooth() ? kLobeSpecularReflection : kLobeGlossyReflection;
        if (hasCosineLobe()) f |= l_.diffuse ? kLobeDiffuseReflection : kLobeGlossyReflection;
        if (l_.conductorBase) f |= kLobeGlossyReflection;
        if (l_.transmission)
            f |= l_.transmission->isSmooth() ? kLobeSpecularTransmission : kLobeGlossyTransmission;
        return f;
    }

    /// Lobe selection probabilities (specular, diffuse, transmission, conductor base) for wo.
    std::array<Float, 4> lobeProbabilities(const V3& wo) const {
        const Float F = !l_.interface ? Float(0)
                        : reflectsInside(wo)
                            ? insideFresnel(wo, V3(0, 0, 1)).average()
                            : l_.interface->fresnel().evaluate(std::abs(wo.z)).average();
        const Float t = l_.transmissionWeight;
        std::array<Float, 4> w{};
        const Float mu = std::abs(wo.z);
        if (l_.interface) w[0] = std::max(F, Float(0));
        if (l_.diffuse) {
            Float coupling = Float(1) - F;
            if (l_.coupling == LayerCoupling::Sum) coupling = Float(1);
            if (l_.coupling == LayerCoupling::Albedo)
                coupling = Float(1) - (*l_.interfaceAlbedo)(mu);
            w[1] =
                (Float(1) - t) * std::max(l_.diffuse->reflectance().average(), Float(0)) * coupling;
        }
        if (l_.interfaceMultiscatter)
            w[1] += std::max(l_.interfaceMultiscatter->albedo(mu).average(), Float(0));
        if (l_.transmission) w[2] = t * (Float(1) - F);
        if (l_.conductorBase) {
            const V3 o(wo.x, wo.y, mu);
            Float coupling = Float(1) - F;
            if (l_.coupling == LayerCoupling::Sum) coupling = Float(1);
            if (l_.coupling == LayerCoupling::Albedo)
                coupling = sqr(Float(1) - Float((*l_.interfaceAlbedo)(mu)));
            w[3] = l_.conductorBase->albedoEstimate(o) * coupling;
        }
        const bool present[4] = {l_.interface.has_value(), hasCosineLobe(),
                                 l_.transmission.has_value(), l_.conductorBase.has_value()};
        const int n = int(present[0]) + int(present[1]) + int(present[2]) + int(present[3]);
        const Float total = w[0] + w[1] + w[2] + w[3];
        std::array<Float, 4> p{};
        if (n == 0) return p;
        for (int i = 0; i < 4; ++i) {
            if (!present[i]) continue;
            p[i] = total > Float(0) ? Float(0.9) * w[i] / total + Float(0.1) / Float(n)
                                    : Float(1) / Float(n);
        }
        return p;
    }

  private:
    bool hasCosineLobe() const {
        return l_.diffuse.has_value() || l_.interfaceMultiscatter.has_value();
    }

    bool interfaceSmooth() const { return l_.interface && l_.interface->isSmooth(); }

    S evalReflection(const V3& wo, const V3& wi, TransportMode mode, bool inside) const {
        S result(Float(0));
        reflectionTerms(wo, wi, mode, inside, [&](const S& term, bool) { result += term; });
        return result;
    }

    // Whether a pair on wo's side below the surface is inside the material: it transmits, and
    // its microfacet interface then reflects with the Fresnel seen from inside.
    bool reflectsInside(const V3& wo) const {
        return wo.z < Float(0) && l_.transmission && l_.interface && l_.interface->microfacet();
    }

    // F of the interface for light inside the material arriving along `wo` (z < 0) on the
    // microfacet of outward normal m: what transmissionFresnelFactor does not let out.
    S insideFresnel(const V3& wo, const V3& m) const {
        return S(Float(1)) - transmissionFresnelFactor(wo, m);
    }

    // The terms of the reflection (wo, wi above the surface: a pair inside the material,
    // `inside`, mirrored), in the order evalReflection adds them, each with whether it is the
    // interface's own reflection: add(term, interface).
    template <typename Add>
    void reflectionTerms(const V3& wo, const V3& wi, TransportMode mode, bool inside,
                         Add&& add) const {
        if (l_.interface && !interfaceSmooth()) {
            if (inside) {
                // The mirrored half vector is the microfacet's outward normal; the light
                // arrives along -wo.
                const auto m = MicrofacetReflectionLobe<S>::halfVector(wo, wi);
                if (m)
                    add(insideFresnel(-wo, *m) *
                            l_.interface->microfacet()->evalWithoutFresnel(wo, wi),
                        true);
            } else {
                add(l_.interface->eval(wo, wi), true);
            }
        }
        if (l_.interfaceMultiscatter) add(l_.interfaceMultiscatter->eval(wo, wi), false);
        if (l_.diffuse) {
            S coupling(Float(1));
            if (l_.coupling == LayerCoupling::Fresnel && l_.interface)
                coupling = S(Float(1)) - l_.interface->fresnelAt(wo, wi);
            if (l_.coupling == LayerCoupling::Albedo) {
                const AlbedoTable& e = *l_.interfaceAlbedo;
                coupling = S((Float(1) - e(wo.z)) * (Float(1) - e(wi.z)) /
                             std::max(Float(1e-6), Float(1) - Float(e.average())));
            }
            add(l_.diffuse->eval(wo, wi, mode) * coupling * (Float(1) - l_.transmissionWeight),
                false);
        }
        if (l_.conductorBase) {
            const S f = l_.conductorBase->eval(wo, wi, mode);
            if (!f.isZero()) add(f * conductorCoupling(wo, wi), false);
        }
    }

    // The Mueller matrix of the interface's reflection of value `value` for the pair (wo, wi)
    // on either side: its Fresnel model on the half vector, seen from that side.
    MuellerMatrix<S> interfaceMueller(const S& value, const V3& wo, const V3& wi) const {
        if (l_.interface->isPhong()) return depolarising(value);
        const Fresnel<S>& f = l_.interface->fresnel();
        // Inside an exact dielectric the amplitudes are those of the inverse index (total
        // internal reflection's phase included); an approximation keeps the outside's shape.
        if (reflectsInside(wo) && f.kind == FresnelKind::ExactDielectric && !f.film)
            return twoSidedReflectionMueller(value, Fresnel<S>::dielectric(S(Float(1)) / f.eta), wo,
                                             wi);
        return twoSidedReflectionMueller(value, f, wo, wi);
    }

    // W_c of the conductor base (the top of this file).
    S conductorCoupling(const V3& wo, const V3& wi) const {
        if (l_.coupling == LayerCoupling::Sum || !l_.interface) return S(Float(1));
        if (l_.coupling == LayerCoupling::Albedo) {
            const AlbedoTable& e = *l_.interfaceAlbedo;
            return S((Float(1) - Float(e(wo.z))) * (Float(1) - Float(e(wi.z))));
        }
        return S(Float(1)) - l_.interface->fresnelAt(wo, wi);
    }

    S evalTransmission(const V3& wo, const V3& wi, TransportMode mode) const {
        if (!l_.transmission) return S(Float(0));
        const auto t = l_.transmission->transmissionWithoutFresnel(wo, wi, mode);
        if (t.value == Float(0)) return S(Float(0));
        return transmissionFresnelFactor(wo, t.m) * (t.value * l_.transmissionWeight);
    }

    // 1 - F of the interface's Fresnel model for light leaving along wo through microfacet m.
    S transmissionFresnelFactor(const V3& wo, const V3& m) const {
        if (!l_.interface) return S(Float(1));
        const Fresnel<S>& fresnel = l_.interface->fresnel();
        const Float c = glm::dot(wo, m);
        if (fresnel.kind == FresnelKind::ExactDielectric) return S(Float(1)) - fresnel.evaluate(c);
        if (c >= Float(0)) return S(Float(1)) - fresnel.evaluate(c);
        // Inside: an approximation is a function of the outside angle (Snell's law).
        const Float eta = l_.transmission->eta();
        const Float sin2Out = sqr(eta) * (Float(1) - sqr(c));
        if (sin2Out >= Float(1)) return S(Float(0));  // total internal reflection
        return S(Float(1)) - fresnel.evaluate(safeSqrt(Float(1) - sin2Out));
    }

    Layers l_;
};

LAMINA_EXTERN_BSDF_VARIANTS(LayeredBxdf)

}  // namespace lamina
