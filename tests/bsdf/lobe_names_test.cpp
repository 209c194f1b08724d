// Lobe kinds in words: the one description of a flags word (`lamina info`) and the names of
// a sample's kind (`lamina bsdf sample`).
#include <gtest/gtest.h>

#include "lamina/bsdf/material_builder.h"

namespace lamina {
namespace {

TEST(LobeNames, EachKindHasAWordForItsFlags) {
    EXPECT_EQ(kLobeKindNames.name(kLobeDiffuseReflection), "diffuse_reflection");
    EXPECT_EQ(kLobeKindNames.name(kLobeSpecularTransmission), "specular_transmission");
    EXPECT_EQ(describeLobes(kLobeDiffuseReflection), "diffuse reflection");
    EXPECT_EQ(describeLobes(kLobeGlossyReflection), "glossy reflection");
    EXPECT_EQ(describeLobes(kLobeSpecularReflection), "specular reflection");
    EXPECT_EQ(describeLobes(kLobeDiffuseTransmission), "diffuse transmission");
    EXPECT_EQ(describeLobes(kLobeGlossyTransmission), "glossy transmission");
    EXPECT_EQ(describeLobes(kLobeSpecularTransmission), "specular transmission");
}

TEST(LobeNames, AFlagsWordListsItsKindsInTableOrder) {
    EXPECT_EQ(describeLobes(kLobeNone), "none (black)");
    EXPECT_EQ(describeLobes(kLobeGlossyReflection | kLobeGlossyTransmission),
              "glossy reflection, glossy transmission");
    // Each kind has a bit of its own: a union lists exactly the kinds it was made of, though
    // diffuse reflection with specular transmission holds the component bits of specular
    // reflection and of diffuse transmission.
    EXPECT_EQ(describeLobes(kLobeDiffuseReflection | kLobeSpecularTransmission),
              "diffuse reflection, specular transmission");
    EXPECT_EQ(describeLobes(kLobeGlossyReflection | kLobeDiffuseTransmission),
              "glossy reflection, diffuse transmission");
    EXPECT_EQ(describeLobes(kLobeAll),
              "diffuse reflection, glossy reflection, specular reflection, diffuse "
              "transmission, glossy transmission, specular transmission");
    // What closes off transmission (a coat) keeps exactly the reflection kinds.
    EXPECT_EQ(reflectionKinds(kLobeAll),
              kLobeDiffuseReflection | kLobeGlossyReflection | kLobeSpecularReflection);
    EXPECT_EQ(reflectionKinds(kLobeDiffuseTransmission), kLobeNone);
}

TEST(LobeNames, DescribeTheLobesOfMaterials) {
    const SpectrumContext<Rgb<double>> context;
    auto lobes = [&](const std::string& json) {
        return describeLobes(buildBxdf(parseMaterialArgument(json), context)->flags());
    };
    EXPECT_EQ(lobes(R"({"type":"standard"})"), "diffuse reflection, glossy reflection");
    EXPECT_EQ(lobes(R"({"type":"dielectric"})"), "specular reflection, specular transmission");
    EXPECT_EQ(lobes(R"({"type":"dielectric","roughness":0.3})"),
              "glossy reflection, glossy transmission");
    EXPECT_EQ(lobes(R"({"type":"lambert","reflectance":0})"), "none (black)");
    EXPECT_EQ(lobes(R"({"type":"diffuse_transmission"})"),
              "diffuse reflection, diffuse transmission");
    EXPECT_EQ(lobes(R"({"type":"diffuse_transmission","transmittance":0})"), "diffuse reflection");
    EXPECT_EQ(lobes(R"({"type":"diffuse_transmission","reflectance":0,"transmittance":0})"),
              "none (black)");
    EXPECT_EQ(lobes(R"({"type":"thin_dielectric"})"), "specular reflection, specular transmission");
}

TEST(LobeNames, ASampleHasOneKindWithAName) {
    const SpectrumContext<Rgb<double>> context;
    const auto glass = buildBxdf(parseMaterialArgument(R"({"type":"dielectric"})"), context);
    const Vec3<double> wo(0, 0, 1);
    const auto reflected = glass->sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    const auto refracted = glass->sample(wo, 0.99, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(reflected && refracted);
    EXPECT_EQ(kLobeKindNames.name(LobeFlags(reflected->flags)), "specular_reflection");
    EXPECT_EQ(kLobeKindNames.name(LobeFlags(refracted->flags)), "specular_transmission");
}

}  // namespace
}  // namespace lamina
