// The documented colour forms mean the same in a scene file as in `lamina bsdf`: a measured
// reflectance {"spectrum": [[nm, value], ...]} for `reflectance` and `base_color` is a
// material's spectrum (exact in spectral mode, its D65 colour in RGB mode), while
// {"texture": name} stays a texture reference.
#include <gtest/gtest.h>

#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/json_reader.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {
namespace {

SceneDesc sceneWithMaterial(const std::string& material) {
    const std::string text = R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"m": )" + material +
                             R"(},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
      "lights": [{"type": "point", "position": [0, 3, 3], "intensity": 1}]
    })";
    return parseScene(text, JsonSource{"colors.json", "."});
}

TEST(SceneColors, MeasuredReflectanceSpectrumIsTheMaterialsSpectrum) {
    const SceneDesc scene = sceneWithMaterial(
        R"({"type": "lambert", "reflectance": {"spectrum": [[360, 0.2], [830, 0.6]]}})");
    const auto& diffuse = scene.materials.at(0).model.as<DiffuseMaterial>();
    ASSERT_TRUE(diffuse.reflectance.spectrum);
    EXPECT_NEAR((*diffuse.reflectance.spectrum)(595.0), 0.4, 1e-12);
    // Its RGB-mode value is its colour, between the two ends of the spectrum.
    EXPECT_GT(diffuse.reflectance.rgb[0], 0.2);
    EXPECT_LT(diffuse.reflectance.rgb[2], 0.6);
}

TEST(SceneColors, MeasuredBaseColourOfAStandardMaterial) {
    const SceneDesc scene = sceneWithMaterial(
        R"({"type": "standard", "base_color": {"spectrum": [[360, 0.9], [830, 0.1]]}})");
    const auto& standard = scene.materials.at(0).model.as<StandardMaterial>();
    ASSERT_TRUE(standard.baseColor.spectrum);
    EXPECT_NEAR((*standard.baseColor.spectrum)(595.0), 0.5, 1e-12);
}

TEST(SceneColors, AnObjectWithoutTextureOrSpectrumIsStillAnError) {
    try {
        sceneWithMaterial(R"({"type": "lambert", "reflectance": {"spektrum": 1}})");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("materials.m.reflectance"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lamina::render
