// The `hair` material: Chiang, Bitterli, Tappan and Burley 2016's fibre (hair_fiber.h) on the
// outside of a closed tube, index-matched inside (docs/bsdf.md, "Hair"). The shading frame's x
// axis must run along the fibre (a `curves` shape gives it; on other shapes x is arbitrary).
//   wo outside (wo.z > 0): f(wo, wi) |cos| = sum_p S_p(wo, wi) with the offset h of wo, over
//        the whole sphere: the lobes that cross the fibre (TT, ...) leave into the tube, whose
//        far wall lets them out.
//   wo inside (wo.z < 0): the wall passes light straight on, a delta wi = -wo of weight 1.
// So light crosses a fibre displaced by its width, and a path meets the same surfaces whether it
// is traced from the camera or from a light. The model is not reciprocal (A_p depends on
// theta_o and h only), so importance transport evaluates the adjoint f*(wo, wi) = f(wi, wo)
// (Veach 1997, eq. 5.14): sum_p S_p(wi, wo) |cos theta_i| / |cos theta_o|, with the delta on
// the other side. sample() draws the pass-through with probability 0.2 from outside and 0.8 from
// inside (it carries radiance only from inside and importance only from outside) and otherwise
// the fibre's lobes for wo, so one density serves both modes.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/hair_fiber.h"
#include "lamina/bsdf/material_builder.h"

namespace lamina {

template <SpectrumType S>
class HairBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    static constexpr double kPassOutside = 0.2;  ///< P(pass-through) for wo outside
    static constexpr double kPassInside = 0.8;   ///< for wo inside

    explicit HairBxdf(const HairFiber<S>& fiber) : fiber_(fiber) {}

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        if (mode == TransportMode::Radiance) return wo.z > Float(0) ? lobes(wo, wi) : zero();
        if (!(wi.z > Float(0)) || wo.z == Float(0)) return zero();
        const S v = lobes(wi, wo) * Float(std::abs(double(wi.z)) / std::abs(double(wo.z)));
        return v.isFinite() ? v : zero();
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        if (wo.z == Float(0)) return Float(0);
        double density = 0;
        fiber_.value(fiber_.incidence(Vec3d(wo)), Vec3d(wi), density);
        return Float((1 - passProbability(wo)) * density);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2& u,
                                        TransportMode mode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const double pass = passProbability(wo);
        if (double(uc) < pass) {
            // The delta carries radiance from inside and importance from outside.
            const bool carries = (mode == TransportMode::Radiance) == (wo.z < Float(0));
            if (!carries) return std::nullopt;
            return BsdfSample<S>{-wo, S(Float(1 / pass)), Float(pass), kLobeSpecularTransmission,
                                 Float(1)};
        }
        const auto in = fiber_.incidence(Vec3d(wo));
        const Vec3d wiD = fiber_.sample(in, (double(uc) - pass) / (1 - pass), Vec2d(u));
        double density = 0;
        fiber_.value(in, wiD, density);
        const Float pdf = Float((1 - pass) * density);
        const V3 wi(wiD);
        if (!(pdf > Float(0)) || wi.z == Float(0)) return std::nullopt;
        // A lobe's direction that carries nothing in this mode keeps its weight of zero (the
        // path ends) rather than vanish, so that the samples keep the density pdf() states.
        const S weight = eval(wo, wi, mode) / pdf;
        if (!weight.isFinite()) return std::nullopt;
        return BsdfSample<S>{
            wi, weight, pdf,
            sameHemisphere(wo, wi) ? kLobeGlossyReflection : kLobeGlossyTransmission, Float(1)};
    }

    std::uint32_t flags() const override {
        return kLobeGlossyReflection | kLobeGlossyTransmission | kLobeSpecularTransmission;
    }

  private:
    static S zero() { return S(Float(0)); }

    static double passProbability(const V3& wo) {
        return wo.z > Float(0) ? kPassOutside : kPassInside;
    }

    S lobes(const V3& wo, const V3& wi) const {
        double density = 0;
        const S v = fiber_.value(fiber_.incidence(Vec3d(wo)), Vec3d(wi), density);
        return v;
    }

    HairFiber<S> fiber_;
};

LAMINA_EXTERN_BSDF_VARIANTS(HairBxdf)

/// Chiang et al. 2016's absorption of a fibre from its melanin concentrations (pbrt-v4's
/// per-channel coefficients of eumelanin and pheomelanin, linear Rec.709).
inline RgbInput hairAbsorptionFromMelanin(double eumelanin, double pheomelanin) {
    return RgbInput(0.419, 0.697, 1.37) * eumelanin + RgbInput(0.187, 0.4, 1.05) * pheomelanin;
}

/// Chiang et al. 2016's inverse of the colour of multiple scattering: the absorption whose
/// fibres look `color` (in (0, 1]) at the azimuthal roughness beta_n.
inline RgbInput hairAbsorptionFromColor(const RgbInput& color, double betaN) {
    const double b = betaN;
    const double d = 5.969 - 0.215 * b + 2.532 * b * b - 10.73 * b * b * b + 5.574 * b * b * b * b +
                     0.245 * b * b * b * b * b;
    RgbInput out;
    for (int c = 0; c < 3; ++c)
        out[c] = sqr(std::log(std::clamp(color[c], 1e-4, 1.0)) / d);
    return out;
}

/// `hair` (hair_reader.cpp): the absorption sigma_a per unit radius, linear Rec.709 (spectral
/// mode upsamples it as an unbounded spectrum), already resolved from melanin or a colour.
struct HairMaterial {
    RgbInput sigmaA = hairAbsorptionFromMelanin(1.3, 0);
    double eta = 1.55;
    double betaM = 0.3;
    double betaN = 0.3;
    double alphaDegrees = 2;
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const HairMaterial& m, const MaterialBuilder<S>& b) {
    return std::make_unique<HairBxdf<S>>(
        HairFiber<S>(m.eta, b.context().unbounded(m.sigmaA), m.betaM, m.betaN, m.alphaDegrees));
}
LAMINA_MATERIAL_MODEL(HairMaterial)

}  // namespace lamina
