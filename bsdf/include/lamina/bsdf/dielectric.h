// A dielectric boundary: smooth (delta reflection + refraction) or rough (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces": BRDF eq. 20, BTDF eq. 21,
// generalised half vector eq. 16), with the exact Fresnel equations and total internal
// reflection. `eta` is eta_inside / eta_outside; a wo below the surface (wo.z < 0) is inside.
//
// Transport mode: radiance crossing into a medium of relative index eta' is compressed into
// a smaller solid angle, so the BTDF carries 1/eta'^2 in radiance mode and not in importance
// mode (Veach 1997, section 5.2). With eta' the relative index along the sampled direction,
//   f_t(wo, wi) |cos_i| = D G2 (1 - F) |wi.m| |wo.m| / (|cos_o| (wi.m + wo.m / eta')^2)  [/
//   eta'^2].
//
// A thin film (thin_film.h) on the outside replaces the Fresnel reflectance F by the film's, a
// spectrum: the lobes are chosen with the probability of its channels' mean and weighted by
// each channel's F / mean (1 - F and 1 - mean for refraction); directions are the bare
// boundary's.
//
// |eta - 1| < kIndexMatched is treated as an index-matched boundary: light passes straight
// through (a delta lobe); with a film it is a free-standing film (a soap bubble), whose
// reflection is then a mirror's. The refracted lobe's width there is ~ |eta - 1| alpha, so this is
// exact to that order, and it keeps float and double in agreement where the generalised half
// vector would suffer catastrophic cancellation.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/microfacet_distribution.h"
#include "lamina/bsdf/polarised_fresnel.h"
#include "lamina/core/fresnel_equations.h"

namespace lamina {

inline constexpr double kIndexMatched = 1e-3;

/// Refracts w (pointing away from the surface, on either side) through a boundary whose normal
/// n points outside, with eta = eta_inside / eta_outside. Returns the transmitted direction
/// and eta' (the relative index along it: eta from outside, 1/eta from inside), or nullopt
/// under total internal reflection.
template <std::floating_point T>
std::optional<std::pair<Vec3<T>, T>> refract(const Vec3<T>& w, Vec3<T> n, T eta) {
    T cosI = glm::dot(n, w);
    if (cosI < T(0)) {  // w is inside: swap the media and flip the normal
        eta = T(1) / eta;
        cosI = -cosI;
        n = -n;
    }
    const T sin2I = std::max(T(0), T(1) - cosI * cosI);
    const T sin2T = sin2I / (eta * eta);
    if (sin2T >= T(1)) return std::nullopt;
    const T cosT = safeSqrt(T(1) - sin2T);
    return std::make_pair(glm::normalize(-w / eta + (cosI / eta - cosT) * n), eta);
}

template <SpectrumType S>
class DielectricBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;
    using Distribution = MicrofacetDistribution<Float>;

    DielectricBxdf(Float eta, const Distribution& distribution,
                   G2Form g2 = G2Form::HeightCorrelated,
                   std::optional<ThinFilm<S>> film = std::nullopt)
        : eta_(eta), distribution_(distribution), g2_(g2), film_(std::move(film)) {}

    Float eta() const { return eta_; }
    const std::optional<ThinFilm<S>>& film() const { return film_; }
    bool indexMatched() const { return std::abs(eta_ - Float(1)) < Float(kIndexMatched); }
    bool isSmooth() const { return indexMatched() || distribution_.effectivelySmooth(); }

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        const auto g = geometry(wo, wi);
        if (!g) return S(Float(0));
        if (film_) {
            const S F = filmReflectance(glm::dot(wo, g->m));
            if (g->reflection)
                return F * (distribution_.D(g->m) * distribution_.G2(wo, wi, g2_) /
                            (Float(4) * std::abs(wo.z)));
            return (S(Float(1)) - F) * btdfWithoutFresnel(wo, wi, *g, mode);
        }
        const Float F = fresnelDielectric(glm::dot(wo, g->m), eta_);
        if (g->reflection) {
            const Float dg = distribution_.D(g->m) * distribution_.G2(wo, wi, g2_);
            return S(dg * F / (Float(4) * std::abs(wo.z)));
        }
        return S(btdfWithoutFresnel(wo, wi, *g, mode) * (Float(1) - F));
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        const auto g = geometry(wo, wi);
        if (!g) return Float(0);
        const Float R = reflectionProbability(glm::dot(wo, g->m));
        const Float dv = visibleDensity(wo, g->m);
        if (g->reflection) return dv / (Float(4) * std::abs(glm::dot(wo, g->m))) * R;
        const Float wim = glm::dot(wi, g->m), wom = glm::dot(wo, g->m);
        return dv * std::abs(wim) / sqr(wim + wom / g->etap) * (Float(1) - R);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        if (isSmooth()) return sampleSmooth(wo, uc, mode);
        const V3 wup = wo.z < Float(0) ? -wo : wo;
        const V3 m = distribution_.sampleVisibleNormal(wup, u);
        const Float wom = glm::dot(wo, m);
        if (wom == Float(0)) return std::nullopt;
        const Float R = reflectionProbability(wom);
        V3 wi;
        std::uint32_t flags;
        Float etap = Float(1);
        if (uc < R) {
            wi = reflect(wo, m);
            if (!sameHemisphere(wo, wi)) return std::nullopt;
            flags = kLobeGlossyReflection;
        } else {
            const auto t = refract(wo, m, eta_);
            if (!t) return std::nullopt;
            wi = t->first;
            etap = t->second;
            if (sameHemisphere(wo, wi) || wi.z == Float(0)) return std::nullopt;
            flags = kLobeGlossyTransmission;
        }
        const Float p = pdf(wo, wi);
        if (!(p > Float(0)) || !std::isfinite(p)) return std::nullopt;
        const S weight = eval(wo, wi, mode) / p;
        if (!weight.isFinite()) return std::nullopt;
        return BsdfSample<S>{wi, weight, p, flags, etap};
    }

    /// Reflection and refraction polarise by the Fresnel amplitudes on each microfacet, with
    /// the phase of total internal reflection.
    MuellerMatrix<S> evalMueller(const V3& wo, const V3& wi, TransportMode mode) const override {
        const auto g = geometry(wo, wi);
        if (!g) return MuellerMatrix<S>();
        return polarised(eval(wo, wi, mode), wo, wi, g->m);
    }

    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        if (!s.isSpecular()) return evalMueller(wo, s.wi, mode) / s.pdf;
        return polarised(s.weight, wo, s.wi, V3(0, 0, 1));
    }

    std::uint32_t flags() const override {
        return isSmooth() ? (kLobeSpecularReflection | kLobeSpecularTransmission)
                          : (kLobeGlossyReflection | kLobeGlossyTransmission);
    }

    /// The geometric part of the BTDF for a transmission pair (wo, wi on opposite sides):
    /// D G2 |wi.m| |wo.m| / (|cos_o| (wi.m + wo.m / eta')^2) [/ eta'^2 in radiance mode],
    /// i.e. f_t |cos_i| without the (1 - F) factor, and the microfacet normal m. Used by the
    /// layered material, which weights it by its own interface's Fresnel model.
    struct Transmission {
        Float value = 0;
        V3 m{0, 0, 1};
    };
    Transmission transmissionWithoutFresnel(const V3& wo, const V3& wi, TransportMode mode) const {
        const auto g = geometry(wo, wi);
        if (!g || g->reflection) return {};
        return {btdfWithoutFresnel(wo, wi, *g, mode), g->m};
    }

    /// Density of sampleRefraction(): visible normal m, refracted (no Fresnel choice).
    Float refractionPdf(const V3& wo, const V3& wi) const {
        const auto g = geometry(wo, wi);
        if (!g || g->reflection) return Float(0);
        const Float wim = glm::dot(wi, g->m), wom = glm::dot(wo, g->m);
        return visibleDensity(wo, g->m) * std::abs(wim) / sqr(wim + wom / g->etap);
    }

    /// Refracts wo through a sampled visible microfacet (rough) or the surface (smooth).
    /// Returns wi and eta', or nullopt under total internal reflection.
    std::optional<std::pair<V3, Float>> sampleRefraction(const V3& wo, const V2& u) const {
        if (wo.z == Float(0)) return std::nullopt;
        if (indexMatched()) return std::make_pair(-wo, Float(1));
        const V3 m = isSmooth() ? V3(0, 0, 1)
                                : distribution_.sampleVisibleNormal(wo.z < Float(0) ? -wo : wo, u);
        const auto t = refract(wo, m, eta_);
        if (!t || sameHemisphere(wo, t->first) || t->first.z == Float(0)) return std::nullopt;
        return t;
    }

  private:
    struct Geometry {
        V3 m;  ///< microfacet normal, m.z > 0
        bool reflection;
        Float etap;  ///< relative index along wi (1 for reflection)
    };

    // The generalised half vector of (wo, wi) and whether the pair is a reflection; nullopt
    // for configurations no microfacet can produce (back-facing microfacets, grazing).
    std::optional<Geometry> geometry(const V3& wo, const V3& wi) const {
        if (isSmooth() || wo.z == Float(0) || wi.z == Float(0)) return std::nullopt;
        const bool reflection = wo.z * wi.z > Float(0);
        const Float etap = reflection ? Float(1) : (wo.z > Float(0) ? eta_ : Float(1) / eta_);
        V3 m = safeNormalize(wi * etap + wo);
        if (m == V3(Float(0))) return std::nullopt;
        if (m.z < Float(0)) m = -m;
        // Both directions must see the microfacet from the side they are on.
        if (glm::dot(m, wi) * wi.z < Float(0) || glm::dot(m, wo) * wo.z < Float(0))
            return std::nullopt;
        return Geometry{m, reflection, etap};
    }

    // Walter's BTDF times |cos_i| without (1 - F), for a transmission geometry.
    Float btdfWithoutFresnel(const V3& wo, const V3& wi, const Geometry& g,
                             TransportMode mode) const {
        const Float wim = glm::dot(wi, g.m), wom = glm::dot(wo, g.m);
        Float ft = distribution_.D(g.m) * distribution_.G2(wo, wi, g2_) * std::abs(wim * wom) /
                   (std::abs(wo.z) * sqr(wim + wom / g.etap));
        if (mode == TransportMode::Radiance) ft /= sqr(g.etap);
        return ft;
    }

    // The Mueller matrix of a lobe value for the pair (wo, wi) on the microfacet m.
    MuellerMatrix<S> polarised(const S& value, const V3& wo, const V3& wi, const V3& m) const {
        if (wo.z * wi.z > Float(0)) {
            Fresnel<S> fresnel =
                Fresnel<S>::dielectric(S(indexMatched() && film_ ? Float(1) : eta_));
            fresnel.film = film_;
            return reflectionMueller(value, fresnel, wo, wi);
        }
        // Light crosses from wi's side to wo's.
        const Float etaLight = wi.z > Float(0) ? eta_ : Float(1) / eta_;
        return transmissionMueller(value, indexMatched() ? Float(1) : etaLight, wo, wi, m,
                                   film_ ? &*film_ : nullptr);
    }

    // Visible-normal density of m seen from wo's side.
    Float visibleDensity(const V3& wo, const V3& m) const {
        return distribution_.visibleNormalPdf(wo.z < Float(0) ? -wo : wo, m);
    }

    // The film's reflectance at the cosine `cosTheta` to the microfacet normal (negative: from
    // inside); index-matched, the free-standing film's (air on both sides).
    S filmReflectance(Float cosTheta) const {
        return film_->reflectance(
            ThinFilm<S>::dielectricSide(cosTheta, indexMatched() ? Float(1) : eta_));
    }

    // The probability of choosing reflection: F, or the mean of the film's F.
    Float reflectionProbability(Float cosTheta) const {
        return film_ ? filmReflectance(cosTheta).average() : fresnelDielectric(cosTheta, eta_);
    }

    std::optional<BsdfSample<S>> sampleSmooth(const V3& wo, Float uc, TransportMode mode) const {
        if (film_) return sampleSmoothFilm(wo, uc, mode);
        const Float R = indexMatched() ? Float(0) : fresnelDielectric(wo.z, eta_);
        if (uc < R) {
            return BsdfSample<S>{V3(-wo.x, -wo.y, wo.z), S(Float(1)), R, kLobeSpecularReflection,
                                 Float(1)};
        }
        if (indexMatched())  // straight through, no bending and no 1/eta'^2 worth keeping
            return BsdfSample<S>{-wo, S(Float(1)), Float(1), kLobeSpecularTransmission, Float(1)};
        const auto t = refract(wo, V3(0, 0, 1), eta_);
        // R = 1 under total internal reflection; at grazing angles R can also round to 1
        // without TIR (float), leaving no probability for this branch.
        if (!t || !(Float(1) - R > Float(0))) return std::nullopt;
        const Float scale = mode == TransportMode::Radiance ? Float(1) / sqr(t->second) : Float(1);
        return BsdfSample<S>{t->first, S(scale), Float(1) - R, kLobeSpecularTransmission,
                             t->second};
    }

    // sampleSmooth with a film: the mirror with the probability of the film's mean F, weighted
    // by F / mean; refraction (straight through when index-matched) with the rest.
    std::optional<BsdfSample<S>> sampleSmoothFilm(const V3& wo, Float uc,
                                                  TransportMode mode) const {
        const S F = filmReflectance(wo.z);
        const Float R = F.average();
        if (uc < R)
            return BsdfSample<S>{V3(-wo.x, -wo.y, wo.z), F / R, R, kLobeSpecularReflection,
                                 Float(1)};
        if (!(Float(1) - R > Float(0))) return std::nullopt;
        const S weight = (S(Float(1)) - F) / (Float(1) - R);
        if (indexMatched())
            return BsdfSample<S>{-wo, weight, Float(1) - R, kLobeSpecularTransmission, Float(1)};
        const auto t = refract(wo, V3(0, 0, 1), eta_);
        if (!t) return std::nullopt;
        const Float scale = mode == TransportMode::Radiance ? Float(1) / sqr(t->second) : Float(1);
        return BsdfSample<S>{t->first, weight * scale, Float(1) - R, kLobeSpecularTransmission,
                             t->second};
    }

    Float eta_;
    Distribution distribution_;
    G2Form g2_;
    std::optional<ThinFilm<S>> film_;
};

LAMINA_EXTERN_BSDF_VARIANTS(DielectricBxdf)

/// `dielectric` (dielectric_reader.cpp): a boundary between outside (index 1) and inside
/// (index ior).
struct DielectricMaterial {
    double ior = 1.5;  ///< the RGB-mode index (n at 587.56 nm for a dispersive glass)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< a named glass or an ior_file
    MicrofacetParams microfacet;
    std::optional<ThinFilmParams> thinFilm;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const DielectricMaterial& d, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    const Float eta = d.spectrum ? b.context().dielectricIor(*d.spectrum) : Float(d.ior);
    return std::make_unique<DielectricBxdf<S>>(eta, b.distribution(d.microfacet), d.microfacet.g2,
                                               b.thinFilm(d.thinFilm));
}
LAMINA_MATERIAL_MODEL(DielectricMaterial)

}  // namespace lamina
