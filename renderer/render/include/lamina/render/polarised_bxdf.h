// The polarised mode's view of a BSDF at one shading point: the spectral BSDF's Mueller
// matrices (evalMueller, sampleMueller: in the canonical frames of its local directions)
// turned into the canonical frames of the world directions (stokesAxis of each), so that the
// matrices of consecutive vertices meet in the same frame (docs/polarisation.md, "Frames along
// a path"). Sampling and densities are the spectral BSDF's.
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
        return inWorldFrames(bsdf_->evalMueller(wo, wi, mode), wo, wi);
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override { return bsdf_->pdf(wo, wi); }
    std::optional<BsdfSample<PolarisedSpectrum>> sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                        TransportMode mode) const override {
        const auto s = bsdf_->sample(wo, uc, u, mode);
        if (!s) return std::nullopt;
        return BsdfSample<PolarisedSpectrum>{
            s->wi, inWorldFrames(bsdf_->sampleMueller(wo, *s, mode), wo, s->wi), s->pdf, s->flags,
            s->eta};
    }
    std::uint32_t flags() const override { return bsdf_->flags(); }
    bool usesLobeChoice() const override { return bsdf_->usesLobeChoice(); }

  private:
    // Light arrives propagating along -wi and leaves along wo (local directions).
    PolarisedSpectrum inWorldFrames(PolarisedSpectrum::Base m, const Vec3f& wo,
                                    const Vec3f& wi) const {
        const Vec3f in = frame_.toWorld(-wi), out = frame_.toWorld(wo);
        turnInputFrame(
            m, frameTurn(StokesFrame<float>{in, stokesAxis(in)}, frame_.toWorld(stokesAxis(-wi))));
        turnOutputFrame(
            m, frameTurn(StokesFrame<float>{out, frame_.toWorld(stokesAxis(wo))}, stokesAxis(out)));
        return m;
    }

    const Spectral* bsdf_ = nullptr;
    Frame<float> frame_;
};

}  // namespace lamina::render
