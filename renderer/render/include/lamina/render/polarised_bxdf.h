// The polarised mode's view of a BSDF at one shading point: the spectral BSDF's Mueller
// matrices (evalMueller, sampleMueller: in the canonical frames of its local directions)
// turned into the canonical frames of the world directions (stokesAxis of each), so that the
// matrices of consecutive vertices meet in the same frame (docs/polarisation.md, "Frames along
// a path"). Sampling and densities are the spectral BSDF's.
//
// In importance mode (light paths) the matrices are those of the physical event, light
// arriving along -wo and leaving along wi: the camera path's event with the directions
// swapped (evalMueller(wi, wo) in radiance mode), scaled per wavelength so that [0][0] is the
// adjoint BSDF's value, eval(wo, wi) in importance mode, which differs by the radiance
// factor 1/eta^2 of refraction (docs/polarisation.md, "Light paths"). So a light path's
// throughput is the product of its matrices in the order light meets them, as a camera path's
// is in the reverse order, and both end in the same frames.
#pragma once

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/frame.h"
#include "lamina/render/polarised_spectrum.h"

namespace lamina::render {

class PolarisedBxdf final : public Bxdf<PolarisedSpectrum> {
  public:
    using Spectral = Bxdf<SampledSpectrum<float>>;

    /// Rebinds this view to `bsdf` at a point with shading frame `frame`.
    void bind(const Spectral& bsdf, const Frame<float>& frame) {
        bsdf_ = &bsdf;
        frame_ = frame;
    }

    PolarisedSpectrum eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const override {
        if (mode == TransportMode::Radiance)
            return inWorldFrames(bsdf_->evalMueller(wo, wi, mode), wo, wi);
        return withUnpolarised(
            inWorldFrames(bsdf_->evalMueller(wi, wo, TransportMode::Radiance), wi, wo),
            bsdf_->eval(wo, wi, mode));
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override { return bsdf_->pdf(wo, wi); }
    std::optional<BsdfSample<PolarisedSpectrum>> sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                        TransportMode mode) const override {
        const auto s = bsdf_->sample(wo, uc, u, mode);
        if (!s) return std::nullopt;
        if (mode == TransportMode::Radiance)
            return BsdfSample<PolarisedSpectrum>{
                s->wi,  inWorldFrames(bsdf_->sampleMueller(wo, *s, mode), wo, s->wi),
                s->pdf, s->flags,
                s->eta, s->component};
        // The physical event of a delta lobe is its sample seen from the other end, drawn by
        // the same material of every mix (BsdfSample::component), with the adjoint's weight:
        // its matrix is already the light path's (no rescaling, which would undo the
        // polarised [0][0] of a thin_dielectric's slab, docs/polarisation.md).
        if (s->isSpecular()) {
            const BsdfSample<SampledSpectrum<float>> reversed{
                wo,
                s->weight,
                s->pdf,
                s->flags,
                s->isTransmission() ? 1.0f / s->eta : s->eta,
                s->component};
            return BsdfSample<PolarisedSpectrum>{
                s->wi,
                inWorldFrames(bsdf_->sampleMueller(s->wi, reversed, TransportMode::Radiance), s->wi, wo),
                s->pdf,
                s->flags,
                s->eta,
                s->component};
        }
        const PolarisedSpectrum::Base m = bsdf_->evalMueller(s->wi, wo, TransportMode::Radiance);
        return BsdfSample<PolarisedSpectrum>{
            s->wi,  withUnpolarised(inWorldFrames(m, s->wi, wo), s->weight),
            s->pdf, s->flags,
            s->eta, s->component};
    }
    std::uint32_t flags() const override { return bsdf_->flags(); }
    bool usesLobeChoice() const override { return bsdf_->usesLobeChoice(); }

  private:
    // m scaled per wavelength so that its [0][0] is `value`; a wavelength where m has no
    // [0][0] to scale becomes the depolariser of `value`.
    static PolarisedSpectrum withUnpolarised(PolarisedSpectrum m,
                                             const SampledSpectrum<float>& value) {
        for (int i = 0; i < PolarisedSpectrum::kSize; ++i) {
            const float m00 = m.m[0][0][i];
            const float k = m00 > 0.0f ? value[i] / m00 : 0.0f;
            for (auto& row : m.m)
                for (auto& e : row)
                    e[i] *= k;
            m.m[0][0][i] = value[i];
        }
        return m;
    }

    // Light arrives propagating along -wi and leaves along wo (local directions).
    PolarisedSpectrum inWorldFrames(PolarisedSpectrum::Base m, const Vec3f& wo,
                                    const Vec3f& wi) const {
        const Vec3f in = frame_.toWorld(-wi), out = frame_.toWorld(wo);
        turnInputFrame(m, doubledFrameTurn(StokesFrame<float>{in, stokesAxis(in)},
                                           frame_.toWorld(stokesAxis(-wi))));
        turnOutputFrame(m, doubledFrameTurn(StokesFrame<float>{out, frame_.toWorld(stokesAxis(wo))},
                                            stokesAxis(out)));
        return m;
    }

    const Spectral* bsdf_ = nullptr;
    Frame<float> frame_;
};

}  // namespace lamina::render
