// A thin optical sheet that light crosses without turning: an ideal linear polariser or an
// ideal linear retarder (a wave plate), the two elements of the `polariser` and `retarder`
// materials (docs/polarisation.md, "Optical sheets"). One delta lobe: straight transmission,
// wi = -wo, with the sheet's Mueller matrix (mueller_matrix.h): for the polariser of
// transmittance T, T times linearPolariser(phi); for the retarder of retardance delta,
// linearRetarder(phi, delta); phi is the angle of the sheet's axis, projected perpendicular to
// the light, from the light's canonical frame axis (stokesAxis). At oblique incidence this is
// the ideal element seen along the ray, not a model of a real sheet's angular behaviour.
//
// The unpolarised modes see [0][0]: the polariser is a grey filter of T / 2 (every polariser
// halves unpolarised light, whatever its angle), the retarder a clear sheet (1). So two crossed
// polarisers pass T^2 / 4 there, where the polarised mode gives 0: the point of the material.
//
// The axis is a direction in the shading frame (z the normal); the material gives it in the
// world and the polarised mode turns it into each hit's frame (MaterialKind::orient).
// The sheet joins the same medium on both sides: the sample's eta is 1.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/mueller_matrix.h"

namespace lamina {

template <SpectrumType S>
class OpticalSheetBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    enum class Element { Polariser, Retarder };

    /// `axis`: the transmission axis (polariser) or the fast axis (retarder) in the shading
    /// frame; `transmittance`: the polariser's T; `retardance`: the retarder's delta (radians).
    OpticalSheetBxdf(Element element, const V3& axis, Float transmittance, Float retardance)
        : element_(element), axis_(axis), transmittance_(transmittance), retardance_(retardance) {}

    S eval(const V3&, const V3&, TransportMode) const override { return S(Float(0)); }
    Float pdf(const V3&, const V3&) const override { return Float(0); }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float, const V2&,
                                        TransportMode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        return BsdfSample<S>{-wo, S(unpolarised()), Float(1), kLobeSpecularTransmission, Float(1)};
    }

    /// The element seen by light travelling along wo (arriving along -wi = wo): both frames are
    /// wo's canonical one.
    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>&,
                                   TransportMode) const override {
        const MuellerMatrix<Float> m = element(wo);
        MuellerMatrix<S> out;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                out(r, c) = S(m(r, c));
        return out;
    }

    std::uint32_t flags() const override { return kLobeSpecularTransmission; }
    bool usesLobeChoice() const override { return false; }

    /// The element's Mueller matrix for light travelling along d (unit), in d's canonical frame.
    MuellerMatrix<Float> element(const V3& d) const {
        const V3 x = stokesAxis(d);
        V3 a = axis_ - glm::dot(axis_, d) * d;
        // Light along the axis sees no axis: any is as good (the sheet is seen edge-on, which
        // a ray crossing it never is).
        const Float len = glm::length(a);
        const Float phi =
            len > Float(1e-6) ? frameTurn(StokesFrame<Float>{d, x}, V3(a / len)) : Float(0);
        if (element_ == Element::Polariser) return linearPolariser(phi) * transmittance_;
        return linearRetarder(phi, retardance_);
    }

  private:
    Float unpolarised() const {
        return element_ == Element::Polariser ? Float(0.5) * transmittance_ : Float(1);
    }

    Element element_;
    V3 axis_;
    Float transmittance_, retardance_;
};

LAMINA_EXTERN_BSDF_VARIANTS(OpticalSheetBxdf)

/// `polariser`: an ideal linear polariser sheet (optical_sheet_reader.cpp). `axis`: the
/// transmission axis, in the world as the scene gives it, in the shading frame once the polarised
/// mode has turned it (MaterialKind::orient); unit length.
struct PolariserMaterial {
    Vec3d axis{1, 0, 0};
    double transmittance = 1;  ///< of light polarised along the axis
};

/// `retarder`: an ideal linear retarder sheet, a wave plate (optical_sheet_reader.cpp). `axis`:
/// the fast axis, as PolariserMaterial's.
struct RetarderMaterial {
    Vec3d axis{1, 0, 0};
    double retardanceDegrees = 90;  ///< the slow component's lag, at every wavelength
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const PolariserMaterial& p, const MaterialBuilder<S>&) {
    using Float = typename S::Float;
    return std::make_unique<OpticalSheetBxdf<S>>(OpticalSheetBxdf<S>::Element::Polariser,
                                                 Vec3<Float>(p.axis), Float(p.transmittance),
                                                 Float(0));
}
LAMINA_MATERIAL_MODEL(PolariserMaterial)

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const RetarderMaterial& r, const MaterialBuilder<S>&) {
    using Float = typename S::Float;
    return std::make_unique<OpticalSheetBxdf<S>>(OpticalSheetBxdf<S>::Element::Retarder,
                                                 Vec3<Float>(r.axis), Float(1),
                                                 Float(r.retardanceDegrees * kPi<double> / 180.0));
}
LAMINA_MATERIAL_MODEL(RetarderMaterial)

}  // namespace lamina
