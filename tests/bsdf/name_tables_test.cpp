// The name tables of the bsdf enumerations: every value has exactly one name, names lead back
// to their values, and the material parser accepts every name of each table it reads by.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/error.h"

namespace lamina {
namespace {

template <typename E, std::size_t N, std::size_t M>
void expectEveryValueNamed(const NameTable<E, N>& table, const std::array<E, M>& everyValue,
                           const char* what) {
    EXPECT_EQ(N, M) << what << ": one entry per value";
    std::set<std::string_view> names;
    for (const E value : everyValue) {
        const std::string_view name = table.name(value);
        EXPECT_NE(name, "?") << what << ": value " << int(value) << " has no name";
        EXPECT_EQ(table.find(name), value) << what << ": " << name;
        EXPECT_EQ(table.name(*table.find(name)), name) << what;
        EXPECT_TRUE(names.insert(name).second) << what << ": \"" << name << "\" twice";
    }
    EXPECT_FALSE(table.find("no such name").has_value()) << what;
}

TEST(NameTables, EveryValueOfEveryBsdfEnumerationHasANameThatRoundTrips) {
    expectEveryValueNamed(
        kNdfKindNames, std::array{NdfKind::Ggx, NdfKind::Beckmann, NdfKind::BlinnPhong}, "NdfKind");
    expectEveryValueNamed(kG2FormNames, std::array{G2Form::HeightCorrelated, G2Form::Separable},
                          "G2Form");
    expectEveryValueNamed(
        kMicrofacetSamplingNames,
        std::array{MicrofacetSampling::VisibleNormals, MicrofacetSampling::SphericalCaps,
                   MicrofacetSampling::Walter, MicrofacetSampling::WalterWidened},
        "MicrofacetSampling");
    expectEveryValueNamed(
        kLayerCouplingNames,
        std::array{LayerCoupling::Fresnel, LayerCoupling::Sum, LayerCoupling::Albedo},
        "LayerCoupling");
    expectEveryValueNamed(kDiffuseModelNames,
                          std::array{DiffuseModel::Lambert, DiffuseModel::OrenNayar,
                                     DiffuseModel::Burley, DiffuseModel::Frostbite},
                          "DiffuseModel");
    expectEveryValueNamed(
        kFresnelChoiceNames,
        std::array{FresnelChoice::Auto, FresnelChoice::Schlick, FresnelChoice::SchlickShadowed,
                   FresnelChoice::SchlickSphericalGaussian, FresnelChoice::F82,
                   FresnelChoice::Exact},
        "FresnelChoice");
    expectEveryValueNamed(
        kSpecularModelNames,
        std::array{SpecularModel::Ggx, SpecularModel::Beckmann, SpecularModel::Phong},
        "SpecularModel");
    expectEveryValueNamed(kTransportModeNames,
                          std::array{TransportMode::Radiance, TransportMode::Importance},
                          "TransportMode");
    expectEveryValueNamed(
        kLobeKindNames,
        std::array{kLobeDiffuseReflection, kLobeGlossyReflection, kLobeSpecularReflection,
                   kLobeDiffuseTransmission, kLobeGlossyTransmission, kLobeSpecularTransmission},
        "lobe kinds");
}

MaterialDesc parse(const std::string& json) {
    return parseMaterialArgument(json);
}

// A conductor with the given extra key, e.g. "sampling":"caps".
ConductorMaterial conductor(const std::string& key, std::string_view name) {
    const MaterialDesc d = parse(R"({"type":"conductor","material":"Au","roughness":0.3,")" + key +
                                 R"(":")" + std::string(name) + "\"}");
    return d.model.as<ConductorMaterial>();
}

StandardMaterial standard(const std::string& key, std::string_view name) {
    const MaterialDesc d =
        parse(R"({"type":"standard",")" + key + R"(":")" + std::string(name) + "\"}");
    return d.model.as<StandardMaterial>();
}

TEST(NameTables, TheMaterialParserReadsEveryNameOfItsTables) {
    for (const auto& [value, name] : kNdfKindNames.entries())
        EXPECT_EQ(conductor("distribution", name).microfacet.ndf, value) << name;
    for (const auto& [value, name] : kG2FormNames.entries())
        EXPECT_EQ(conductor("g2", name).microfacet.g2, value) << name;
    for (const auto& [value, name] : kMicrofacetSamplingNames.entries())
        EXPECT_EQ(conductor("sampling", name).microfacet.sampling, value) << name;
    for (const auto& [value, name] : kFresnelChoiceNames.entries())
        EXPECT_EQ(conductor("fresnel", name).fresnel, value) << name;
    for (const auto& [value, name] : kLayerCouplingNames.entries())
        EXPECT_EQ(standard("coupling", name).coupling, value) << name;
    for (const auto& [value, name] : kDiffuseModelNames.entries())
        EXPECT_EQ(standard("diffuse_model", name).diffuse, value) << name;
    EXPECT_FALSE(standard("diffuse_model", "none").diffuse.has_value());
    for (const auto& [value, name] : kSpecularModelNames.entries()) {
        const StandardMaterial s = standard("specular_model", name);
        EXPECT_TRUE(s.specularLobe) << name;
        EXPECT_EQ(s.phong, value == SpecularModel::Phong) << name;
        EXPECT_EQ(s.microfacet.ndf,
                  value == SpecularModel::Beckmann ? NdfKind::Beckmann : NdfKind::Ggx)
            << name;
    }
    EXPECT_FALSE(standard("specular_model", "none").specularLobe);
}

TEST(NameTables, TheUnknownTypeMessageListsEveryMaterialType) {
    std::string list;
    for (const auto& name : materialTypeNames()) {
        list += (list.empty() ? "" : ", ") + name;
        // these need more keys
        if (name != "conductor" && name != "layered" && name != "mix" && name != "coated" &&
            name != "polariser" && name != "retarder" && name != "measured") {
            EXPECT_EQ(parse(R"({"type":")" + name + "\"}").type, name);
        }
    }
    EXPECT_EQ(list,
              "standard, lambert, oren_nayar, burley, frostbite, conductor, "
              "diffuse_transmission, dielectric, thin_dielectric, phong, layered, mix, coated, "
              "polariser, retarder, measured, hair");
    try {
        parse(R"({"type":"plastic"})");
        FAIL() << "accepted an unknown material type";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected one of " + list), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lamina
