// A coat's base takes its colour from a texture (MaterialKind::texturedThrough; pbrt-v4's
// coateddiffuse with a textured reflectance): at each uv the textured coat is the coat over a
// base of that colour, the scene's material itself is left as read, and what a nested material
// cannot take is refused naming its key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/scene/material_textures.h"
#include "lamina/scene/scene_description.h"
#include "render_helpers.h"

namespace lamina {
namespace {

// A checkerboard of 0.8 / 0.2 in 2 x 2 cells of uv (cell (0, 0) is `a`, as in pbrt-v4) under
// a rough coat of index 1.5; the same coat over constant bases of 0.8 and 0.2 beside it.
constexpr const char* kScene = R"({
  "textures": {"checks": {"type": "checkerboard", "a": 0.8, "b": 0.2, "scale": [2, 2]}},
  "materials": {
    "textured": {"type": "coated", "ior": 1.5, "roughness": 0.3,
                 "base": {"type": "lambert", "reflectance": {"texture": "checks"}}},
    "light": {"type": "coated", "ior": 1.5, "roughness": 0.3,
              "base": {"type": "lambert", "reflectance": 0.8}},
    "dark": {"type": "coated", "ior": 1.5, "roughness": 0.3,
             "base": {"type": "lambert", "reflectance": 0.2}}},
  "shapes": [{"type": "sphere", "material": "textured", "emission": {"radiance": 1}},
             {"type": "sphere", "material": "light", "center": [3, 0, 0]},
             {"type": "sphere", "material": "dark", "center": [6, 0, 0]}]
})";

int materialIndex(const render::SceneDesc& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.materialNames.size(); ++i)
        if (scene.materialNames[i] == name) return int(i);
    ADD_FAILURE() << "no material " << name;
    return 0;
}

double baseReflectance(const MaterialDesc& coated) {
    const auto& base = *coated.model.as<CoatedMaterial>().base;
    return base.model.as<DiffuseMaterial>().reflectance.rgb[0];
}

TEST(CoatedTexture, TheBaseTakesTheTexturesColourAtEachUv) {
    const render::SceneDesc scene = testing::sceneFromText(kScene);
    const int textured = materialIndex(scene, "textured");
    EXPECT_EQ(scene.materialTextures[std::size_t(textured)].color >= 0, true);
    const MaterialDesc inA = render::texturedMaterial(scene, textured, Vec2<float>(0.25f, 0.25f));
    const MaterialDesc inB = render::texturedMaterial(scene, textured, Vec2<float>(0.75f, 0.25f));
    // Textures hold floats: the texel is 0.8 to float precision.
    EXPECT_NEAR(baseReflectance(inA), 0.8, 1e-7);
    EXPECT_NEAR(baseReflectance(inB), 0.2, 1e-7);
    // The scene's material keeps the placeholder it was read with: each hit copies the base.
    EXPECT_DOUBLE_EQ(baseReflectance(scene.materials[std::size_t(textured)]), 0.5);

    // The textured coat is the coat over a constant base of the texel's colour: the same BSDF
    // value for every pair of directions (the coat's random walk, seeded alike, is the same),
    // up to the float texel (relative 1e-6).
    const MaterialDesc& light = scene.materials[std::size_t(materialIndex(scene, "light"))];
    const MaterialDesc& dark = scene.materials[std::size_t(materialIndex(scene, "dark"))];
    const SpectrumContext<Rgb<double>> rgb{};
    const auto texturedA = buildBxdf(inA, rgb, 7), constantA = buildBxdf(light, rgb, 7);
    const auto texturedB = buildBxdf(inB, rgb, 7), constantB = buildBxdf(dark, rgb, 7);
    const Vec3<double> wo = normalize(Vec3<double>(0.3, -0.2, 0.9));
    for (const Vec3<double>& wi : {Vec3<double>(0, 0, 1), normalize(Vec3<double>(-0.5, 0.1, 0.6)),
                                   normalize(Vec3<double>(0.7, 0.7, 0.2))}) {
        const Rgb<double> a = texturedA->eval(wo, wi, TransportMode::Radiance);
        const Rgb<double> b = texturedB->eval(wo, wi, TransportMode::Radiance);
        const double ca = constantA->eval(wo, wi, TransportMode::Radiance)[0];
        const double cb = constantB->eval(wo, wi, TransportMode::Radiance)[0];
        EXPECT_NEAR(a[0], ca, 1e-6 * ca);
        EXPECT_NEAR(b[0], cb, 1e-6 * cb);
        EXPECT_GT(a[0], b[0]);  // a brighter base under the same coat reflects more
    }
}

// The coat's own roughness from a texture (pbrt-v4's coateddiffuse and coatedconductor, Mitsuba's
// roughplastic): at each uv the coat of the texel's roughness, the base's colour texture beside
// it; over a base with a delta lobe the coat stays rough where the texture says 0 (a smooth coat
// over it is refused).
TEST(CoatedTexture, TheCoatTakesItsOwnRoughnessFromATexture) {
    const render::SceneDesc scene = testing::sceneFromText(R"({
  "textures": {"r": {"type": "checkerboard", "a": 0.2, "b": 0.6, "scale": [2, 2]},
               "zero": {"type": "checkerboard", "a": 0, "b": 0.5, "scale": [2, 2]},
               "checks": {"type": "checkerboard", "a": 0.8, "b": 0.2, "scale": [2, 2]}},
  "materials": {
    "textured": {"type": "coated", "ior": 1.5, "roughness": {"texture": "r"},
                 "base": {"type": "lambert", "reflectance": {"texture": "checks"}}},
    "constant": {"type": "coated", "ior": 1.5, "roughness": 0.6,
                 "base": {"type": "lambert", "reflectance": 0.2}},
    "mirror": {"type": "coated", "roughness": {"texture": "zero"},
               "base": {"type": "conductor", "material": "Au"}}},
  "shapes": [{"type": "sphere", "material": "textured", "emission": {"radiance": 1}},
             {"type": "sphere", "material": "constant", "center": [3, 0, 0]},
             {"type": "sphere", "material": "mirror", "center": [6, 0, 0]}]
})");
    const int textured = materialIndex(scene, "textured");
    const auto alphaOf = [](const MaterialDesc& m) {
        return m.model.as<CoatedMaterial>().microfacet.alphaX;
    };
    const MaterialDesc inA = render::texturedMaterial(scene, textured, Vec2<float>(0.25f, 0.25f));
    const MaterialDesc inB = render::texturedMaterial(scene, textured, Vec2<float>(0.75f, 0.25f));
    EXPECT_NEAR(alphaOf(inA), 0.04, 1e-7);  // alpha = roughness^2
    EXPECT_NEAR(alphaOf(inB), 0.36, 1e-7);
    EXPECT_NEAR(baseReflectance(inA), 0.8, 1e-7);
    EXPECT_NEAR(baseReflectance(inB), 0.2, 1e-7);
    // The coat at a texel is the constant coat of that roughness and base colour.
    const SpectrumContext<Rgb<double>> rgb{};
    const auto atB = buildBxdf(inB, rgb, 7);
    const auto constant =
        buildBxdf(scene.materials[std::size_t(materialIndex(scene, "constant"))], rgb, 7);
    const Vec3<double> wo = normalize(Vec3<double>(0.3, -0.2, 0.9));
    for (const Vec3<double>& wi :
         {Vec3<double>(0, 0, 1), normalize(Vec3<double>(-0.5, 0.1, 0.6))}) {
        const double a = atB->eval(wo, wi, TransportMode::Radiance)[0];
        const double c = constant->eval(wo, wi, TransportMode::Radiance)[0];
        EXPECT_NEAR(a, c, 1e-5 * c);
    }
    // Over the smooth gold, the texel of roughness 0 keeps the smallest rough alpha.
    const int mirror = materialIndex(scene, "mirror");
    const MaterialDesc smooth = render::texturedMaterial(scene, mirror, Vec2<float>(0.25f, 0.25f));
    EXPECT_GE(alphaOf(smooth), double(kSmoothAlpha));
    EXPECT_NO_THROW(buildBxdf(smooth, rgb, 7));
}

TEST(CoatedTexture, WhatANestedMaterialCannotTakeIsRefused) {
    const auto errorOf = [](const std::string& base) {
        try {
            testing::sceneFromText(R"({"textures": {"r": {"type": "checkerboard"}},
              "materials": {"m": {"type": "coated", "base": )" +
                                   base + R"(}},
              "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"({"type": "lambert", "displacement": {"texture": "r"}})"),
                ::testing::HasSubstr("materials.m.base.displacement: a nested material takes no "
                                     "bump or normal map: give it to the outer material"));
    EXPECT_THAT(errorOf(R"({"type": "oren_nayar", "roughness": {"texture": "r"}})"),
                ::testing::HasSubstr("materials.m.base: a textured roughness inside a coated "
                                     "material is not supported (its colour may be textured)"));
    EXPECT_THAT(errorOf(R"({"type": "conductor", "f0": {"texture": "r"}})"),
                ::testing::HasSubstr("materials.m.base.f0: a conductor material cannot take "
                                     "\"f0\" from a texture"));
    // The coat's own keys take none.
    EXPECT_THAT(errorOf(R"({"type": "lambert"}, "ior": {"texture": "r"})"),
                ::testing::HasSubstr("a coated material cannot take \"ior\" from a texture"));
}

}  // namespace
}  // namespace lamina
