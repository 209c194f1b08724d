// Textures: image lookups (sRGB decoding, bilinear, repeat), a checkerboard driving a
// material's colour in a render, textured roughness, and the errors.
#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "lamina/render/texture.h"
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
    // 2 x 2 pixels: top row 0 and 255, bottom row 128 and 64 (all channels equal).
    const unsigned char px[12] = {0, 0, 0, 255, 255, 255, 128, 128, 128, 64, 64, 64};
    {
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open(file.string(), OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px));
        out->close();
    }
    const render::ImageTexture srgb(file, Vec2<float>(1.0f), true);
    const render::ImageTexture linear(file, Vec2<float>(1.0f), false);
    // Texel centres: (u, v) = (0.25, 0.75) is the top-left texel (v = 0 at the bottom).
    EXPECT_NEAR(srgb.evaluate({0.75f, 0.75f})[0], 1.0, 1e-6);
    EXPECT_NEAR(srgb.evaluate({0.25f, 0.25f})[0], srgbToLinear(128 / 255.0), 1e-6);
    EXPECT_NEAR(linear.evaluate({0.25f, 0.25f})[0], 128 / 255.0, 1e-6);
    // Half-way between the bottom texels, and repeating beyond [0, 1).
    EXPECT_NEAR(srgb.evaluate({0.5f, 0.25f})[1],
                0.5 * (srgbToLinear(128 / 255.0) + srgbToLinear(64 / 255.0)), 1e-6);
    EXPECT_NEAR(srgb.evaluate({1.75f, -0.25f})[2], srgb.evaluate({0.75f, 0.75f})[2], 1e-6);
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

}  // namespace
}  // namespace lamina
