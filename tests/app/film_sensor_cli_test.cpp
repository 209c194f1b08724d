// The film's sensor and crop on the command line: a clamp is written into the EXR's metadata
// and printed by `lamina info` (it biases the image), RGB mode says once what its white balance
// approximates, and a crop is written as its own pixels.
#include <gtest/gtest.h>

#include "cli_helpers.h"
#include "lamina/output/image_output.h"

namespace lamina {
namespace {

constexpr const char* kScene = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
  "film": {"resolution": [16, 12], "max_component_value": 0.5, "white_balance": 5000,
           "iso": 200, "crop": [4, 12, 2, 8]},
  "materials": {"white": {"type": "lambert", "reflectance": 0.8}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "white"}],
  "lights": [{"type": "environment", "radiance": 1}]
})";

class FilmSensorCli : public CliTest {};

TEST_F(FilmSensorCli, TheClampIsInTheMetadataAndInInfo) {
    const std::string scene = write("scene.json", kScene);
    const std::string out = (dir_ / "a.exr").string();
    const CommandRun rgb = runLaminaStderr("render " + scene + " -q --spp 2 -o " + out);
    EXPECT_EQ(rgb.exitCode, 0) << rgb.output;
    // One warning in RGB mode, none in spectral mode.
    EXPECT_EQ(rgb.output,
              "lamina: warning: RGB mode white-balances the Rec.709 colours its paths carry (CIE "
              "1931 XYZ of each sample); spectral mode integrates the spectra against the "
              "sensor's curves (--mode spectral)\n");
    EXPECT_EQ(runLaminaStderr("render " + scene + " -q --spp 2 --mode spectral -o " + out).output,
              "");
    const render::RgbImage image = render::readRgbImage(out);
    EXPECT_EQ(image.width, 8);
    EXPECT_EQ(image.height, 6);
    EXPECT_EQ(image.metadata.at("lamina:max_component_value"), "0.5");
    EXPECT_EQ(image.metadata.at("lamina:clamp").rfind("on: ", 0), 0u);
    EXPECT_EQ(image.metadata.at("lamina:imaging_ratio"), "2");
    EXPECT_EQ(image.metadata.at("lamina:white_balance"), "5000");
    const CommandRun info = runLamina("info " + scene);
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("sensor: clamp on (biased)"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("crop: pixels [4, 12) x [2, 8) of the image (8x6 written)"),
              std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("sensor: imaging ratio 2"), std::string::npos) << info.output;
}

}  // namespace
}  // namespace lamina
