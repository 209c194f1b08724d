// The polarised mode's view of a BSDF (polarised_bxdf.h): on a light path (importance mode)
// a delta lobe's matrix is the physical event's, light arriving along -wo and leaving along wi,
// which the camera path samples in radiance mode from the other end. Checked for a smooth
// dielectric's reflection and for thin_dielectric, whose slab matrix has a
// polarised [0][0] that differs from its unpolarised weight (docs/polarisation.md). Broken once
// on purpose: rescaling the light path's delta matrices to the unpolarised weight (as the
// non-delta lobes are rescaled to the adjoint's value) fails the thin slab's reflection.
#include <gtest/gtest.h>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/thin_dielectric.h"
#include "lamina/render/polarised_bxdf.h"

namespace lamina::render {
namespace {

using Spectral = SampledSpectrum<float>;

/// The polarised sample of `bsdf` from wo with the lobe choice uc, in `mode`.
PolarisedSpectrum polarisedSample(const Bxdf<Spectral>& bsdf, const Vec3f& wo, float uc,
                                  TransportMode mode, Vec3f* wi = nullptr) {
    PolarisedBxdf view;
    view.bind(bsdf, Frame<float>::fromNormal(Vec3f(0.0f, 0.0f, 1.0f)));
    const auto s = view.sample(wo, uc, {0.5f, 0.5f}, mode);
    EXPECT_TRUE(s.has_value());
    if (!s) return {};
    if (wi) *wi = s->wi;
    return s->weight;
}

/// The light path's sample from wo against the camera path's sample of the same physical
/// event from the other end (light arriving along -wo, leaving along wi), both per unit of
/// their choice probability, which is the same for these lobes.
void expectLightPathMatrixIsThePhysicalEvent(const Bxdf<Spectral>& bsdf, const Vec3f& wo, float uc,
                                             const std::string& what) {
    Vec3f wi;
    const PolarisedSpectrum light = polarisedSample(bsdf, wo, uc, TransportMode::Importance, &wi);
    Vec3f back;
    const PolarisedSpectrum camera = polarisedSample(bsdf, wi, uc, TransportMode::Radiance, &back);
    ASSERT_LT(glm::length(back - wo), 1e-5f) << what << ": the reverse sample is another event";
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < PolarisedSpectrum::kSize; ++i)
                EXPECT_NEAR(light.m[r][c][i], camera.m[r][c][i],
                            2e-5f * std::max(1.0f, std::abs(camera.m[0][0][i])))
                    << what << " element " << r << c << " wavelength " << i;
}

TEST(PolarisedBxdf, ALightPathsDeltaMatrixIsTheEventTheCameraPathSamplesBackwards) {
    const Vec3f wo = glm::normalize(Vec3f(0.5f, -0.3f, 0.6f));
    const Spectral eta(1.5f);
    const ThinDielectricBxdf<Spectral> thin(eta);
    expectLightPathMatrixIsThePhysicalEvent(thin, wo, 0.0f, "thin slab reflection");
    expectLightPathMatrixIsThePhysicalEvent(thin, wo, 0.999f, "thin slab transmission");
    const DielectricBxdf<Spectral> glass(1.5f, MicrofacetDistribution<float>(NdfKind::Ggx, 0, 0));
    expectLightPathMatrixIsThePhysicalEvent(glass, wo, 0.0f, "glass reflection");
}

}  // namespace
}  // namespace lamina::render
