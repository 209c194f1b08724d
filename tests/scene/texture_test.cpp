// Textures: image lookups (sRGB decoding, bilinear, repeat, invert), a checkerboard driving a
// material's colour in a render, textured roughness, the scale and mix operations (exact
// values), and the errors (reference cycles among them).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "lamina/bsdf/material_kind.h"
#include "lamina/output/image_output.h"
#include "lamina/scene/texture.h"
#include "render_helpers.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

double srgbToLinear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(ImageTexture, DecodesSrgbAndInterpolatesBilinearly) {
    const fs::path file =
        fs::temp_directory_path() / ("lamina-tex-" + std::to_string(::getpid()) + ".png");
    // 2 x 2 pixels: top row 0 and 255, bottom row 128 and 64 (all channels equal). Written by
    // lamina's PNG writer, read through the OpenImageIO module.
    const int bytes[12] = {0, 0, 0, 255, 255, 255, 128, 128, 128, 64, 64, 64};
    std::vector<float> px;
    for (int b : bytes)
        px.push_back(float(b) / 255.0f);
    render::writeRgb8(file, 2, 2, px);
    const render::ImageTexture srgb(file, Vec2<float>(1.0f), true, false);
    const render::ImageTexture linear(file, Vec2<float>(1.0f), false, false);
    // Texel centres: (u, v) = (0.25, 0.75) is the top-left texel (v = 0 at the bottom).
    EXPECT_NEAR(srgb.evaluate(Vec2<float>(0.75f, 0.75f))[0], 1.0, 1e-6);
    EXPECT_NEAR(srgb.evaluate(Vec2<float>(0.25f, 0.25f))[0], srgbToLinear(128 / 255.0), 1e-6);
    EXPECT_NEAR(linear.evaluate(Vec2<float>(0.25f, 0.25f))[0], 128 / 255.0, 1e-6);
    // Half-way between the bottom texels, and repeating beyond [0, 1).
    EXPECT_NEAR(srgb.evaluate(Vec2<float>(0.5f, 0.25f))[1],
                0.5 * (srgbToLinear(128 / 255.0) + srgbToLinear(64 / 255.0)), 1e-6);
    EXPECT_NEAR(srgb.evaluate(Vec2<float>(1.75f, -0.25f))[2],
                srgb.evaluate(Vec2<float>(0.75f, 0.75f))[2], 1e-6);
    fs::remove(file);
}

TEST(Textures, CheckerboardSetsTheReflectancePerCell) {
    // A floor of Lambert reflectance 0.8 / 0.2 in a checkerboard under a uniform sky of 1,
    // direct lighting only: each pixel's radiance is its cell's reflectance.
    const auto scene = testing::sceneFromText(R"({
      "camera": {"position": [0, 3, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 20},
      "film": {"resolution": [16, 16]},
      "integrator": {"max_depth": 1},
      "textures": {"checks": {"type": "checkerboard", "a": 0.8, "b": 0.2, "scale": [2, 2]}},
      "materials": {"floor": {"type": "lambert", "reflectance": {"texture": "checks"}}},
      "shapes": [{"type": "rectangle", "material": "floor",
                  "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
      "lights": [{"type": "environment", "radiance": 1}]
    })");
    render::RenderOptions o;
    o.spp = 256;
    const auto r = render::renderScene(scene, o);
    int bright = 0, dark = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const double v = r.film->pixel(x, y)[1];
            const double se = std::sqrt(r.film->varianceOfMean(x, y));
            if (std::abs(v - 0.8) < 4 * se + 0.02)
                ++bright;
            else if (std::abs(v - 0.2) < 4 * se + 0.02)
                ++dark;
        }
    // Cell borders blur a few pixels; the rest is one of the two values, in equal shares.
    EXPECT_GT(bright, 100);
    EXPECT_GT(dark, 100);
}

TEST(Textures, InlineMeshUvsMatchTheRectangles) {
    auto render = [](const std::string& shape) {
        render::RenderOptions o;
        o.spp = 4;
        return render::renderScene(testing::sceneFromText(R"({
          "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 50},
          "film": {"resolution": [12, 12]},
          "textures": {"c": {"type": "checkerboard", "scale": [3, 3]}},
          "materials": {"m": {"type": "lambert", "reflectance": {"texture": "c"}}},
          "shapes": [)" + shape + R"(],
          "lights": [{"type": "environment", "radiance": 1}]})"),
                                   o);
    };
    const auto rect = render(R"({"type": "rectangle", "material": "m"})");
    const auto mesh = render(R"({"type": "mesh", "material": "m",
        "positions": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
        "uvs": [[0, 0], [1, 0], [1, 1], [0, 1]], "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]],
        "faces": [[0, 1, 2, 3]]})");
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x)
            ASSERT_EQ(rect.film->pixel(x, y)[0], mesh.film->pixel(x, y)[0]);
}

TEST(Textures, ErrorsNameTheTexture) {
    try {
        testing::sceneFromText(R"({
          "materials": {"m": {"type": "lambert", "reflectance": {"texture": "nope"}}},
          "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr(
                                  "materials.m.reflectance.texture: unknown texture \"nope\""));
    }
    try {
        testing::sceneFromText(R"({
          "textures": {"r": {"type": "checkerboard"}},
          "materials": {"m": {"type": "conductor", "f0": 1, "multiscatter": true, "roughness": {"texture": "r"}}},
          "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("cannot use the albedo tables"));
    }
    try {
        testing::sceneFromText(R"({
          "textures": {"img": {"type": "image", "file": "/nonexistent/tex.png"}},
          "shapes": [{"type": "sphere", "material": {"type": "lambert", "reflectance": {"texture": "img"}},
                      "emission": {"radiance": 1}}]})");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("textures.img.file"));
    }
}

// Which keys take a texture is each material type's registration (material_kind.h): another key
// naming a texture is refused there, with what the type and the others can take.
TEST(Textures, OnlyATypesTexturableKeysTakeATexture) {
    const auto errorOf = [](const std::string& material) {
        try {
            testing::sceneFromText(R"({"textures": {"r": {"type": "checkerboard"}},
              "materials": {"m": )" +
                                   material + R"(},
              "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"({"type": "conductor", "f0": {"texture": "r"}})"),
                ::testing::HasSubstr("materials.m.f0: a conductor material cannot take \"f0\" "
                                     "from a texture (it can: roughness)"));
    EXPECT_THAT(errorOf(R"({"type": "lambert", "roughness": {"texture": "r"}})"),
                ::testing::HasSubstr("a lambert material cannot take \"roughness\" from a "
                                     "texture (it can: reflectance)"));
    EXPECT_THAT(errorOf(R"({"type": "mix", "weight": {"texture": "r"},
                             "a": {"type": "lambert"}, "b": {"type": "lambert"}})"),
                ::testing::HasSubstr("a mix material cannot take \"weight\" from a texture; "
                                     "textured parameters: standard (base_color / roughness)"));
    for (const MaterialKind* kind : materialKinds())
        for (const TexturableKey& t : kind->texturable) {
            // Every registered key does take one (a conductor needs its optics, a coat its
            // base, every other type's defaults are a material).
            const std::string extra = kind->name == "conductor" ? R"(, "f0": 0.9)"
                                      : kind->name == "coated"  ? R"(, "base": {"type": "lambert"})"
                                                                : "";
            const std::string material = std::string(R"({"type": ")") + std::string(kind->name) +
                                         R"(", ")" + std::string(t.key) + R"(": {"texture": "r"})" +
                                         extra + "}";
            EXPECT_EQ(errorOf(material), "no error") << material;
        }
}

TEST(Textures, UnusedTexturesAndMaterialsAreNeverLoaded) {
    // A scene pays only for what it uses: the missing image and the unknown metal are never
    // read because no shape refers to them.
    const auto scene = testing::sceneFromText(R"({
      "textures": {"img": {"type": "image", "file": "/nonexistent/tex.png"}},
      "materials": {"used": {"type": "lambert"},
                    "gold": {"type": "conductor", "nk_file": "/nonexistent/au.yml"}},
      "shapes": [{"type": "sphere", "material": "used", "emission": {"radiance": 1}}]})");
    EXPECT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.textures.size(), 0u);
    EXPECT_EQ(scene.unusedMaterialNames, std::vector<std::string>{"gold"});
    EXPECT_EQ(scene.unusedTextureNames, std::vector<std::string>{"img"});
}

// The texture a scene names, after the scene has read it (a material uses `used`).
std::shared_ptr<const render::Texture> textureOf(const render::SceneDesc& scene,
                                                 const std::string& name) {
    for (std::size_t i = 0; i < scene.textureNames.size(); ++i)
        if (scene.textureNames[i] == name) return scene.textures[i];
    ADD_FAILURE() << "no texture " << name;
    return nullptr;
}

render::SceneDesc sceneWithTextures(const std::string& textures, const std::string& used) {
    return testing::sceneFromText(R"({"textures": )" + textures + R"(,
      "materials": {"m": {"type": "lambert", "reflectance": {"texture": ")" +
                                  used + R"("}}},
      "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
}

TEST(TextureOperations, ScaleAndMixGiveTheirExactValues) {
    // A checkerboard of 0.8 / 0.2 with one cell per unit of uv: (0.25, 0.25) is in an `a`
    // cell, (1.25, 0.25) in a `b` cell. Binary fractions keep every product exact in float.
    const auto scene = sceneWithTextures(R"({
      "checks": {"type": "checkerboard", "a": [0.5, 0.25, 1], "b": [0.125, 0.75, 0], "scale": [1, 1]},
      "half": {"type": "scale", "texture": "checks", "scale": 0.5},
      "grey": {"type": "checkerboard", "a": 0.25, "b": 0.75, "scale": [1, 1]},
      "blend": {"type": "mix", "a": "half", "b": [1, 0.5, 0], "amount": "grey"},
      "fixed": {"type": "mix", "a": [0, 0, 0], "b": 1, "amount": 0.75},
      "defaults": {"type": "mix"},
      "top": {"type": "mix", "a": "blend", "b": "fixed", "amount": 0.5}})",
                                         "top");
    const Vec2<float> inA(0.25f, 0.25f), inB(1.25f, 0.25f);
    const auto half = textureOf(scene, "half"), blend = textureOf(scene, "blend");
    EXPECT_EQ(half->evaluate(inA), Rgb<float>(0.25f, 0.125f, 0.5f));
    EXPECT_EQ(half->evaluate(inB), Rgb<float>(0.0625f, 0.375f, 0.0f));
    // (1 - t) a + t b with t = 0.25 in an `a` cell, 0.75 in a `b` cell.
    EXPECT_EQ(blend->evaluate(inA), Rgb<float>(0.75f * 0.25f + 0.25f * 1.0f,
                                               0.75f * 0.125f + 0.25f * 0.5f, 0.75f * 0.5f));
    EXPECT_EQ(blend->evaluate(inB),
              Rgb<float>(0.25f * 0.0625f + 0.75f * 1.0f, 0.25f * 0.375f + 0.75f * 0.5f, 0.0f));
    EXPECT_EQ(textureOf(scene, "fixed")->evaluate(inA), Rgb<float>(0.75f));
    // The mix named only by "top" is read with it, and so are the textures it names.
    EXPECT_EQ(textureOf(scene, "top")->evaluate(inA),
              (blend->evaluate(inA) + Rgb<float>(0.75f)) * 0.5f);
    EXPECT_TRUE(std::find(scene.unusedTextureNames.begin(), scene.unusedTextureNames.end(),
                          "checks") == scene.unusedTextureNames.end());
    EXPECT_EQ(scene.unusedTextureNames, std::vector<std::string>{"defaults"});
    // pbrt-v4's defaults: a 0, b 1, amount 0.5.
    const auto defaults = sceneWithTextures(R"({"d": {"type": "mix"}})", "d");
    EXPECT_EQ(textureOf(defaults, "d")->evaluate(inA), Rgb<float>(0.5f));
}

// max(0, value)^exponent per channel, after the lookup: 0.25^(1/2) = 0.5, 0.0625^(1/4) = 0.5,
// a negative value (a scale cannot make one, a mix of a negative colour is refused) would be 0.
TEST(TextureOperations, PowerRaisesTheLookedUpValue) {
    const auto scene = sceneWithTextures(R"({
      "checks": {"type": "checkerboard", "a": [0.25, 0.0625, 1], "b": [0, 4, 0.5], "scale": [1, 1]},
      "root": {"type": "power", "texture": "checks", "exponent": 0.5},
      "fourth": {"type": "power", "texture": "root", "exponent": 0.5}})",
                                         "fourth");
    const Vec2<float> inA(0.25f, 0.25f), inB(1.25f, 0.25f);
    EXPECT_EQ(textureOf(scene, "root")->evaluate(inA), Rgb<float>(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(textureOf(scene, "root")->evaluate(inB), Rgb<float>(0.0f, 2.0f, std::sqrt(0.5f)));
    const Rgb<float> fourth = textureOf(scene, "fourth")->evaluate(inA);
    EXPECT_FLOAT_EQ(fourth[0], std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(fourth[1], 0.5f);
    const auto errorOf = [](const std::string& textures) {
        try {
            sceneWithTextures(textures, "p");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"({"c": {"type": "checkerboard"},
                            "p": {"type": "power", "texture": "c", "exponent": 17}})"),
                ::testing::HasSubstr("textures.p.exponent"));
    EXPECT_THAT(
        errorOf(R"({"c": {"type": "checkerboard"}, "p": {"type": "power", "texture": "c"}})"),
        ::testing::HasSubstr("textures.p.exponent"));
}

TEST(TextureOperations, InvertGivesOneMinusTheValue) {
    const fs::path file =
        fs::temp_directory_path() / ("lamina-invert-" + std::to_string(::getpid()) + ".exr");
    // 1 x 1 float pixels (linear): 0.25, 0.5 and 1.5 (above 1: inverted to 0, as pbrt clamps).
    render::writeFloatExr(file, 1, 1, {"R", "G", "B"}, {0.25f, 0.5f, 1.5f});
    const auto scene = sceneWithTextures(R"({
      "plain": {"type": "image", "file": ")" +
                                             file.string() + R"("},
      "inverted": {"type": "image", "file": ")" +
                                             file.string() + R"(", "invert": true},
      "both": {"type": "mix", "a": "plain", "b": "inverted", "amount": 0}})",
                                         "both");
    const Vec2<float> uv(0.5f, 0.5f);  // the texel centre: bilinear weights (1, 0, 0, 0)
    EXPECT_EQ(textureOf(scene, "plain")->evaluate(uv), Rgb<float>(0.25f, 0.5f, 1.5f));
    EXPECT_EQ(textureOf(scene, "inverted")->evaluate(uv), Rgb<float>(0.75f, 0.5f, 0.0f));
    fs::remove(file);
}

TEST(TextureOperations, CyclesAndBadOperandsAreRefused) {
    const auto errorOf = [](const std::string& textures, const std::string& used) {
        try {
            sceneWithTextures(textures, used);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"({"self": {"type": "mix", "a": "self"}})", "self"),
                ::testing::HasSubstr("textures.self.a: the textures refer to each other in a "
                                     "cycle: self -> self"));
    EXPECT_THAT(errorOf(R"({"x": {"type": "scale", "texture": "y", "scale": 2},
                            "y": {"type": "mix", "b": "x"}})",
                        "x"),
                ::testing::HasSubstr("textures.y.b: the textures refer to each other in a "
                                     "cycle: x -> y -> x"));
    EXPECT_THAT(errorOf(R"({"x": {"type": "mix", "amount": "y"},
                            "y": {"type": "mix", "a": "z"}, "z": {"type": "scale", "texture": "y", "scale": 1}})",
                        "x"),
                ::testing::HasSubstr("cycle: y -> z -> y"));
    EXPECT_THAT(errorOf(R"({"s": {"type": "scale", "texture": "nope", "scale": 1}})", "s"),
                ::testing::HasSubstr("textures.s.texture: unknown texture \"nope\""));
    EXPECT_THAT(errorOf(R"({"s": {"type": "scale", "scale": 1}})", "s"),
                ::testing::HasSubstr("textures.s.texture: expected the name of a texture"));
    EXPECT_THAT(errorOf(R"({"m": {"type": "mix", "amount": 1.5}})", "m"),
                ::testing::HasSubstr("textures.m.amount"));
    EXPECT_THAT(errorOf(R"({"m": {"type": "mix", "scale": [1, 1]}})", "m"),
                ::testing::HasSubstr("textures.m"));
}

}  // namespace
}  // namespace lamina
