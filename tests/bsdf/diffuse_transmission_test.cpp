// diffuse_transmission: the values of f, the lobe choice and the furnace albedo
// reflectance + transmittance (the generic properties run over bsdf_cases.h).
#include <gtest/gtest.h>

#include "lamina/bsdf/diffuse_transmission.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/error.h"

namespace lamina {
namespace {

TEST(DiffuseTransmission, EvalIsReflectanceOrTransmittanceOverPi) {
    const DiffuseTransmissionBxdf<Rgbd> bxdf(Rgbd(0.6, 0.3, 0.1), Rgbd(0.2, 0.5, 0.4));
    const Vec3d wo = glm::normalize(Vec3d(0.3, -0.2, 1)), wi = glm::normalize(Vec3d(-1, 0.5, 2));
    for (const double side : {1.0, -1.0}) {
        const Vec3d o = wo * side;
        const Rgbd r = bxdf.eval(o, wi * side, TransportMode::Radiance);
        const Rgbd t = bxdf.eval(o, -wi * side, TransportMode::Importance);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(r[c], Rgbd(0.6, 0.3, 0.1)[c] / kPi<double> * wi.z, 1e-15);
            EXPECT_NEAR(t[c], Rgbd(0.2, 0.5, 0.4)[c] / kPi<double> * wi.z, 1e-15);
        }
        // Lobe choice by max(reflectance) = 0.6 against max(transmittance) = 0.5.
        EXPECT_NEAR(bxdf.pdf(o, wi * side), 0.6 / 1.1 * wi.z / kPi<double>, 1e-15);
        EXPECT_NEAR(bxdf.pdf(o, -wi * side), 0.5 / 1.1 * wi.z / kPi<double>, 1e-15);
    }
}

TEST(DiffuseTransmission, SampleGoesToTheChosenSide) {
    const DiffuseTransmissionBxdf<Rgbd> bxdf(Rgbd(0.5), Rgbd(0.25));
    for (const double woZ : {1.0, -1.0}) {
        const Vec3d wo(0, 0, woZ);
        const auto r = bxdf.sample(wo, 0.1, {0.3, 0.6}, TransportMode::Radiance);
        const auto t = bxdf.sample(wo, 0.9, {0.3, 0.6}, TransportMode::Radiance);
        ASSERT_TRUE(r && t);
        EXPECT_GT(r->wi.z * woZ, 0.0);
        EXPECT_LT(t->wi.z * woZ, 0.0);
        EXPECT_EQ(r->flags, std::uint32_t(kLobeDiffuseReflection));
        EXPECT_EQ(t->flags, std::uint32_t(kLobeDiffuseTransmission));
        EXPECT_EQ(t->eta, 1.0);
    }
}

// The furnace: the albedo at any wo is reflectance + transmittance, both as the expectation of
// the sample weight over the lobe choice (exact: the weight does not depend on the direction
// within a lobe) and as the integral of eval over the sphere (midpoint rule in cos theta and
// phi, which is exact for f |cos| = const |cos| up to rounding).
TEST(DiffuseTransmission, FurnaceAlbedoIsReflectancePlusTransmittance) {
    const SpectrumContext<Rgbd> context;
    const auto bxdf = buildBxdf(
        parseMaterialArgument(R"({"type":"diffuse_transmission","reflectance":[0.7,0.2,0.05],)"
                              R"("transmittance":[0.3,0.6,0.1]})"),
        context);
    const Rgbd expected(1.0, 0.8, 0.15);
    for (const double cosO : {1.0, 0.5, 0.05, -0.3}) {
        const Vec3d wo(std::sqrt(1 - cosO * cosO), 0, cosO);
        const double pr = 0.7 / (0.7 + 0.6);
        const auto r = bxdf->sample(wo, 0.5 * pr, {0.2, 0.7}, TransportMode::Radiance);
        const auto t = bxdf->sample(wo, 0.5 * (1 + pr), {0.2, 0.7}, TransportMode::Radiance);
        ASSERT_TRUE(r && t);
        const Rgbd byChoice = r->weight * pr + t->weight * (1 - pr);
        Rgbd byIntegral(0.0);
        const int n = 256;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double z = -1 + 2 * (i + 0.5) / n, phi = 2 * kPi<double> * (j + 0.5) / n;
                const double s = std::sqrt(1 - z * z);
                const Vec3d wi(s * std::cos(phi), s * std::sin(phi), z);
                byIntegral += bxdf->eval(wo, wi, TransportMode::Radiance) *
                              (4 * kPi<double> / (double(n) * n));
            }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(byChoice[c], expected[c], 1e-12) << "cos theta_o " << cosO;
            EXPECT_NEAR(byIntegral[c], expected[c], 1e-12) << "cos theta_o " << cosO;
        }
    }
}

TEST(DiffuseTransmission, ReflectanceSpectraInSpectralMode) {
    const MaterialDesc desc = parseMaterialArgument(
        R"({"type":"diffuse_transmission","reflectance":{"spectrum":[[360,0.1],[830,0.5]]},)"
        R"("transmittance":{"spectrum":[[360,0.4],[830,0.0]]}})");
    auto lambda = SampledWavelengths<double>::fixed({400, 450, 600, 700});
    const SpectrumContext<SampledSpectrum<double>> context{lambda};
    const auto bxdf = buildBxdf(desc, context);
    const Vec3d wo(0, 0, 1), wi = glm::normalize(Vec3d(1, 0, 1));
    const auto f = bxdf->eval(wo, wi, TransportMode::Radiance);
    const auto g = bxdf->eval(wo, -wi, TransportMode::Radiance);
    for (int i = 0; i < SampledSpectrum<double>::kSize; ++i) {
        const double x = (lambda[i] - 360.0) / 470.0;
        EXPECT_NEAR(f[i], (0.1 + 0.4 * x) / kPi<double> * wi.z, 1e-9);
        EXPECT_NEAR(g[i], (0.4 - 0.4 * x) / kPi<double> * wi.z, 1e-9);
    }
}

TEST(DiffuseTransmission, ParserDefaultsAndRefusals) {
    const auto d = parseMaterialArgument(R"({"type":"diffuse_transmission"})")
                       .model.as<DiffuseTransmissionMaterial>();
    EXPECT_EQ(d.reflectance.rgb, RgbInput(0.25));
    EXPECT_EQ(d.transmittance.rgb, RgbInput(0.25));
    EXPECT_THROW(parseMaterialArgument(R"({"type":"diffuse_transmission","transmittance":1.5})"),
                 InputError);
    EXPECT_THROW(parseMaterialArgument(R"({"type":"diffuse_transmission","roughness":0.5})"),
                 InputError);
    // A coat has no way below its base.
    EXPECT_THROW(
        parseMaterialArgument(R"({"type":"coated","base":{"type":"diffuse_transmission"}})"),
        InputError);
    EXPECT_NO_THROW(parseMaterialArgument(
        R"({"type":"coated","base":{"type":"diffuse_transmission","transmittance":0}})"));
}

}  // namespace
}  // namespace lamina
