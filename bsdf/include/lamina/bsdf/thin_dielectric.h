// A thin dielectric slab (a window pane, a soap film without interference): two parallel smooth
// boundaries so close that light leaves where it entered, as pbrt-v4's ThinDielectricBxDF
// (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 9.5.1).
//
// With R the Fresnel reflectance of one boundary at the incident angle and T = 1 - R, light
// reflects off the first boundary (R) or enters (T) and then bounces between the two, leaving
// at the top after an odd number of internal reflections and at the bottom after an even one.
// Summing the geometric series of the internal bounces (R^2 per round trip):
//   R' = R + T^2 R (1 + R^2 + R^4 + ...) = R + T^2 R / (1 - R^2) = 2R / (1 + R),
//   T' = T^2 (1 + R^2 + ...) = T^2 / (1 - R^2) = (1 - R) / (1 + R) = 1 - R'.
// (The angle inside is the refracted one at both boundaries, so R is the same at each.)
// Both lobes are deltas: the mirror direction and -wo (the two refractions cancel, so the
// transmitted ray is not bent, and no dispersion either). eta is per channel (per wavelength in
// spectral mode): R' varies with it, the directions do not. Transmission crosses back into the
// same medium, so radiance is not scaled (the sample's eta is 1).
//
// Polarised (docs/polarisation.md), the series is summed for s and p apart, with the s-p
// correlation (incoherent_slab.h): the slab reflects (R'_s + R'_p) / 2 of unpolarised light,
// not R' of the averaged R above, and transmits partly polarised light (a pile-of-plates
// polariser of one plate). So unlike the other materials, its [0][0] is not the unpolarised
// value: the slab is many Fresnel events in one, and the difference is what averaging s and p
// at each of them costs.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/polarised_fresnel.h"
#include "lamina/core/fresnel_equations.h"
#include "lamina/core/incoherent_slab.h"

namespace lamina {

template <SpectrumType S>
class ThinDielectricBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    /// `eta`: the slab's index relative to the medium around it, per channel.
    explicit ThinDielectricBxdf(const S& eta) : eta_(eta) {}

    /// R' at |cos theta| = cosTheta (the slab is symmetric: either side).
    S reflectance(Float cosTheta) const {
        S r;
        for (int i = 0; i < S::kSize; ++i) {
            const Float R = fresnelDielectric(std::abs(cosTheta), eta_[i]);
            r[i] = Float(2) * R / (Float(1) + R);
        }
        return r;
    }

    S eval(const V3&, const V3&, TransportMode) const override { return S(Float(0)); }
    Float pdf(const V3&, const V3&) const override { return Float(0); }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float uc, const V2&,
                                        TransportMode) const override {
        if (wo.z == Float(0)) return std::nullopt;
        const S r = reflectance(wo.z);
        const S t = S(Float(1)) - r;
        // Choose by the mean over channels: each channel's weight is its R' (or T') over the
        // probability of the choice, which is exact for every channel.
        const Float p = clamp(r.average(), Float(0), Float(1));
        if (uc < p)
            return BsdfSample<S>{V3(-wo.x, -wo.y, wo.z), r / p, p, kLobeSpecularReflection,
                                 Float(1)};
        if (!(Float(1) - p > Float(0))) return std::nullopt;
        return BsdfSample<S>{-wo, t / (Float(1) - p), Float(1) - p, kLobeSpecularTransmission,
                             Float(1)};
    }

    /// The slab's reflection or transmission Mueller matrix over the lobe's probability. Light
    /// arrives along -wi and leaves along wo, whichever way the path was built (both lobes are
    /// symmetric under the exchange).
    MuellerMatrix<S> sampleMueller(const V3& wo, const BsdfSample<S>& s,
                                   TransportMode) const override {
        const bool transmission = s.isTransmission();
        MuellerMatrix<S> m;
        for (int i = 0; i < S::kSize; ++i) {
            const SlabMueller<Float> slab = incoherentSlabMueller(std::abs(wo.z), eta_[i]);
            const MuellerMatrix<Float>& channel =
                transmission ? slab.transmission : slab.reflection;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    m(r, c)[i] = channel(r, c);
        }
        return inCanonicalFrames(m, -s.wi, wo, V3(0, 0, 1)) / s.pdf;
    }

    std::uint32_t flags() const override {
        return kLobeSpecularReflection | kLobeSpecularTransmission;
    }

  private:
    S eta_;
};

LAMINA_EXTERN_BSDF_VARIANTS(ThinDielectricBxdf)

/// `thin_dielectric`: a thin slab of glass (dielectric_reader.cpp); ior as `dielectric` reads it.
struct ThinDielectricMaterial {
    double ior = 1.5;  ///< the RGB-mode index (n at 587.56 nm for a dispersive glass)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< a named glass or an ior_file
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const ThinDielectricMaterial& t, const MaterialBuilder<S>& b) {
    using Float = typename S::Float;
    return std::make_unique<ThinDielectricBxdf<S>>(
        t.spectrum ? b.context().indexPerChannel(*t.spectrum) : S(Float(t.ior)));
}
LAMINA_MATERIAL_MODEL(ThinDielectricMaterial)

}  // namespace lamina
