// A rough conductor under the dielectric interface of a layered stack (layered.h), seen from
// outside: the first-order model of Weidlich and Wilkie 2007 ("Arbitrarily layered micro-facet
// surfaces", GRAPHITE 2007, section 4), with the interface's roughness left to the interface's
// own lobe.
//
// Light from wi enters the coat of relative index eta, is refracted by Snell's law at the
// geometric normal into wi', reflects once off the conductor towards wo' and leaves along wo.
// Radiance entering a medium of index eta is multiplied by eta^2 and divided by it again on the
// way out, and the solid angles map by cos theta_i dw_i = eta^2 cos theta_i' dw_i' (the
// invariance of n^2 cos dw, Veach 1997, eq. 5.4), so the part of f that crosses the interface is
//
//   f(wo, wi) = W(wo, wi) f_base(wo', wi') / eta^2,
//
// with W the transmittance of the way in and out (the stack's coupling, layered.h). This class
// is that term without W: eval = f_base(wo', wi') cos theta_i / eta^2 = base.eval(wo', wi')
// cos theta_i / (eta^2 cos theta_i'). It is reciprocal when f_base is (wo and wi play the same
// roles), and with W <= 1 it conserves energy: integrating over wi with the solid-angle map above
// gives at most the base's directional albedo at wo'. Light the base sends outside the critical
// cone (total internal reflection) and light the interface reflects back down are not followed:
// this is one pass through the coat.
//
// sample() samples the base at wo' and refracts the result out, so its density at wi is the
// base's density at wi' times dw_i'/dw_i = cos theta_i / (eta^2 cos theta_i'): eval / pdf is the
// base's own weight. Directions are in the upper hemisphere (the stack mirrors them there).
#pragma once

#include <optional>

#include "lamina/bsdf/conductor.h"

namespace lamina {

template <SpectrumType S>
class RefractedConductorLobe {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    using V2 = Vec2<Float>;

    /// `eta`: the interface's index relative to the outside; the base's optics are relative to
    /// the interface's medium.
    RefractedConductorLobe(const ConductorBxdf<S>& base, Float eta) : base_(base), eta_(eta) {}

    const ConductorBxdf<S>& base() const { return base_; }
    Float eta() const { return eta_; }

    /// The direction inside the coat (pointing up, away from the base) of a direction `w` above
    /// it: Snell's law at the geometric normal keeps the tangential direction and divides its
    /// length by eta. nullopt when light cannot enter (eta < 1 beyond the critical angle).
    std::optional<V3> inside(const V3& w) const { return bend(w, Float(1) / eta_); }

    /// The direction above the coat of a direction `w` inside it; nullopt under total internal
    /// reflection.
    std::optional<V3> outside(const V3& w) const { return bend(w, eta_); }

    S eval(const V3& wo, const V3& wi, TransportMode mode) const {
        const auto o = inside(wo), i = inside(wi);
        if (!o || !i) return S(Float(0));
        return base_.eval(*o, *i, mode) * jacobian(wi, *i);
    }

    Float pdf(const V3& wo, const V3& wi) const {
        const auto o = inside(wo), i = inside(wi);
        if (!o || !i) return Float(0);
        return base_.pdf(*o, *i) * jacobian(wi, *i);
    }

    /// A direction drawn from pdf(wo, .): the base sampled at wo', refracted out.
    std::optional<V3> sample(const V3& wo, Float uc, const V2& u, TransportMode mode) const {
        const auto o = inside(wo);
        if (!o) return std::nullopt;
        const auto r = base_.sample(*o, uc, u, mode);
        if (!r || !(r->wi.z > Float(0))) return std::nullopt;
        const auto wi = outside(r->wi);
        if (!wi || !(wi->z > Float(0))) return std::nullopt;
        return wi;
    }

    /// A cheap estimate of the lobe's albedo at wo for choosing lobes: the base's Fresnel
    /// reflectance at cos theta_o' (0 if wo cannot enter).
    Float albedoEstimate(const V3& wo) const {
        const auto o = inside(wo);
        if (!o) return Float(0);
        return std::max(base_.lobe().fresnel().evaluate(o->z).average(), Float(0));
    }

  private:
    // The direction whose tangential part is `scale` times w's, on the same side; nullopt for
    // w below the surface or when that part is longer than 1. An index-matched interface (eta
    // exactly 1) bends nothing, so that a coat of index 1 is exactly the bare base.
    std::optional<V3> bend(const V3& w, Float scale) const {
        if (!(w.z > Float(0))) return std::nullopt;
        if (eta_ == Float(1)) return w;
        const Float x = w.x * scale, y = w.y * scale;
        const Float sin2 = x * x + y * y;
        if (!(sin2 < Float(1))) return std::nullopt;
        return V3(x, y, std::sqrt(Float(1) - sin2));
    }

    // dw_i' / dw_i = cos theta_i / (eta^2 cos theta_i') (see the top of this file).
    Float jacobian(const V3& wi, const V3& wiInside) const {
        if (eta_ == Float(1)) return Float(1);
        return wiInside.z > Float(0) ? wi.z / (eta_ * eta_ * wiInside.z) : Float(0);
    }

    ConductorBxdf<S> base_;
    Float eta_;
};

}  // namespace lamina
