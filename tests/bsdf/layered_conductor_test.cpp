// The layered stack over a conductor base (bsdf/refracted_conductor.h): the reader's keys and
// refusals, and the limit a coat of index 1 must reach, in every variant. The catalogue
// (tests/support/bsdf_cases.h, "layered_conductor_*") adds its exact properties and chi-square;
// layered_conductor_walk_test.cpp its agreement with the random walk and its energy.
#include <gtest/gtest.h>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/error.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"

namespace lamina {
namespace {

const char* kBareGold = R"({"type":"conductor","material":"Au","roughness":0.3})";

std::string overGold(double ior, const std::string& coupling) {
    return R"({"type":"layered","interface":{"roughness":0.4,"fresnel":"exact","ior":)" +
           std::to_string(ior) + R"(},"base":)" + kBareGold + R"(,"coupling":")" + coupling +
           R"("})";
}

// eval of the coat of index 1 against the bare conductor at random pairs, relative `tolerance`.
template <SpectrumType S, typename Context>
void expectIndexMatchedCoatIsTheBase(const Context& context, double tolerance) {
    using T = typename S::Float;
    const auto bare = buildBxdf(parseMaterialArgument(kBareGold), context);
    for (const char* coupling : {"fresnel", "albedo", "sum"}) {
        const auto coat = buildBxdf(parseMaterialArgument(overGold(1.0, coupling)), context);
        Pcg32 rng(5);
        int nonZero = 0;
        for (int i = 0; i < 500; ++i) {
            const Vec3<T> wo =
                squareToCosineHemisphere(Vec2<T>(T(rng.nextDouble()), T(rng.nextDouble())));
            const Vec3<T> wi =
                squareToCosineHemisphere(Vec2<T>(T(rng.nextDouble()), T(rng.nextDouble())));
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                const S a = coat->eval(wo, wi, mode), b = bare->eval(wo, wi, mode);
                for (int c = 0; c < S::kSize; ++c) {
                    ASSERT_NEAR(double(a[c]), double(b[c]), tolerance * double(b[c]) + 1e-30)
                        << coupling << " channel " << c;
                    nonZero += b[c] > T(0);
                }
            }
        }
        EXPECT_GT(nonZero, 500) << coupling;
    }
}

TEST(LayeredConductor, ACoatOfIndexOneIsTheBareConductorInEveryVariantAndCoupling) {
    expectIndexMatchedCoatIsTheBase<Rgb<double>>(SpectrumContext<Rgb<double>>{}, 1e-12);
    expectIndexMatchedCoatIsTheBase<Rgb<float>>(SpectrumContext<Rgb<float>>{}, 1e-5);
    auto lambdaD = SampledWavelengths<double>::fixed({420, 520, 600, 690});
    expectIndexMatchedCoatIsTheBase<SampledSpectrum<double>>(
        SpectrumContext<SampledSpectrum<double>>{lambdaD}, 1e-12);
    auto lambdaF = SampledWavelengths<float>::fixed({420, 520, 600, 690});
    expectIndexMatchedCoatIsTheBase<SampledSpectrum<float>>(
        SpectrumContext<SampledSpectrum<float>>{lambdaF}, 1e-5);
}

// Helmholtz reciprocity f(wo, wi) = f(wi, wo) in the variants the catalogue does not run.
template <SpectrumType S, typename Context>
void expectReciprocal(const Context& context, double tolerance) {
    using T = typename S::Float;
    for (const char* coupling : {"fresnel", "albedo"}) {
        const auto coat = buildBxdf(parseMaterialArgument(overGold(1.5, coupling)), context);
        Pcg32 rng(9);
        for (int i = 0; i < 500; ++i) {
            const Vec3<T> wo =
                squareToUniformHemisphere(Vec2<T>(T(rng.nextDouble()), T(rng.nextDouble())));
            const Vec3<T> wi =
                squareToUniformHemisphere(Vec2<T>(T(rng.nextDouble()), T(rng.nextDouble())));
            if (wo.z < T(1e-2) || wi.z < T(1e-2)) continue;
            const S a = coat->eval(wo, wi, TransportMode::Radiance) / wi.z;
            const S b = coat->eval(wi, wo, TransportMode::Radiance) / wo.z;
            for (int c = 0; c < S::kSize; ++c) {
                ASSERT_TRUE(std::isfinite(double(a[c])));
                ASSERT_NEAR(double(a[c]), double(b[c]), tolerance * std::max(double(a[c]), 1e-6))
                    << coupling;
            }
        }
    }
}

TEST(LayeredConductor, IsReciprocalInFloatAndInSpectralMode) {
    expectReciprocal<Rgb<float>>(SpectrumContext<Rgb<float>>{}, 1e-3);
    auto lambdaD = SampledWavelengths<double>::fixed({420, 520, 600, 690});
    expectReciprocal<SampledSpectrum<double>>(SpectrumContext<SampledSpectrum<double>>{lambdaD},
                                              1e-9);
}

TEST(LayeredConductor, TheReaderTakesARoughConductorBaseAndRefusesWhatTheStackCannotBe) {
    const MaterialDesc d = parseMaterialArgument(overGold(1.5, "albedo"));
    const auto& s = d.model.as<StandardMaterial>();
    ASSERT_TRUE(s.conductorBase);
    EXPECT_FALSE(s.diffuse.has_value());
    EXPECT_EQ(s.conductorBase->optics.form, ConductorOptics::Form::Spectral);
    EXPECT_DOUBLE_EQ(s.conductorBase->microfacet.alphaX, 0.09);
    EXPECT_TRUE(s.interfaceAlbedo);

    const auto message = [](const std::string& json) {
        try {
            (void)parseMaterialArgument(json);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string smooth =
        message(R"({"type":"layered","base":{"type":"conductor","material":"Au"}})");
    EXPECT_NE(smooth.find("base: a conductor base needs a roughness"), std::string::npos) << smooth;
    const std::string transmission = message(
        R"({"type":"layered","transmission":0.5,"base":{"type":"conductor","f0":0.9,"alpha":0.1}})");
    EXPECT_NE(transmission.find("transmission: a conductor base is opaque"), std::string::npos)
        << transmission;
    const std::string unknown = message(R"({"type":"layered","base":{"type":"mirror"}})");
    EXPECT_NE(unknown.find("base.type: expected one of lambert, oren_nayar, burley, frostbite, "
                           "conductor, got \"mirror\""),
              std::string::npos)
        << unknown;
    const std::string key =
        message(R"({"type":"layered","base":{"type":"conductor","f0":0.9,"alpha":0.1,"x":1}})");
    EXPECT_NE(key.find("base"), std::string::npos) << key;
    EXPECT_NE(key.find("x"), std::string::npos) << key;
}

}  // namespace
}  // namespace lamina
