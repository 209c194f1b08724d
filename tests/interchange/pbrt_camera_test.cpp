// pbrt-v4's film sensor, crop and orthographic camera in lamina's scene document
// (docs/interchange.md, "Camera, film, sampler, integrator"): the translated JSON compared
// exactly, and every refusal naming its file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;

class PbrtCamera : public lamina::testing::ScratchDirectoryTest {
  protected:
    /// A scene of `options` (camera and film lines) and one light.
    ImportedScene import(const std::string& options) {
        file_ = write("s.pbrt", options + "WorldBegin\nLightSource \"point\" \"rgb I\" [1 1 1]\n");
        return importScene(file_, dir_);
    }
    std::string importError(const std::string& options) {
        return errorOf([&] { import(options); });
    }
    std::string at(int line) const {
        return (dir_ / "s.pbrt").string() + ":" + std::to_string(line);
    }
    std::filesystem::path file_;
};

TEST_F(PbrtCamera, TheSensorBecomesTheFilmsSensor) {
    const ImportedScene s = import(
        "Camera \"perspective\" \"float shutteropen\" 0.25 \"float shutterclose\" 0.75\n"
        "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50 \"float iso\" 400\n"
        "  \"float whitebalance\" 5500 \"float maxcomponentvalue\" 10 \"string sensor\" "
        "\"cie1931\"\n");
    EXPECT_EQ(s.scene["film"], Json::parse(R"({"resolution": [100, 50], "iso": 400,
        "exposure_time": 0.5, "white_balance": 5500, "max_component_value": 10,
        "filter": {"type": "gaussian", "radius": 1.5}})"));
    EXPECT_TRUE(s.warnings.empty());
    const SceneDesc scene = loadScene(file_);
    EXPECT_EQ(scene.film.imagingRatio(), 2.0);  // 0.5 s x ISO 400 / 100
    EXPECT_EQ(scene.film.maxComponentValue, 10.0);
    // pbrt-v3's film scale, which exporters keep, multiplies the image.
    EXPECT_EQ(import("Film \"rgb\" \"float scale\" 3\n").scene["film"]["scale"], 3.0);
}

TEST_F(PbrtCamera, CropWindowAndPixelBoundsAsPbrtV4RoundsThem) {
    // ceil(100 x 0.255) = 26, ceil(100 x 0.75) = 75; the pairs are sorted.
    const auto crop = [&](const std::string& params) {
        return import("Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50 " +
                      params + "\n")
            .scene["film"]["crop"];
    };
    EXPECT_EQ(crop("\"float cropwindow\" [0.255 0.75 0.5 0]"), Json::parse("[26, 75, 0, 25]"));
    EXPECT_EQ(crop("\"integer pixelbounds\" [10 20 5 50]"), Json::parse("[10, 20, 5, 50]"));
    const ImportedScene both = import(
        "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50 \"float cropwindow\" "
        "[0 0.5 0 0.5] \"integer pixelbounds\" [200 300 0 120]\n");
    EXPECT_EQ(both.scene["film"]["crop"], Json::parse("[0, 50, 0, 25]"));
    ASSERT_EQ(both.warnings.size(), 1u);
    EXPECT_EQ(both.warnings[0],
              at(1) + ": both cropwindow and pixelbounds: the cropwindow is used");
    // The whole image is no crop at all.
    EXPECT_FALSE(
        import("Film \"rgb\" \"float cropwindow\" [0 1 0 1]\n").scene["film"].contains("crop"));
    const ImportedScene clamped = import(
        "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50 \"integer "
        "pixelbounds\" [90 120 0 10]\n");
    EXPECT_EQ(clamped.scene["film"]["crop"], Json::parse("[90, 100, 0, 10]"));
    EXPECT_EQ(clamped.warnings.at(0),
              at(1) + ": pixelbounds extend beyond the image: clamped to it");
    EXPECT_EQ(importError("Film \"rgb\" \"float cropwindow\" [0.5 0.5 0 1]\n"),
              at(1) + ": the film's crop holds no pixel (pixel bounds [640, 640) x [0, 720))");
    import(
        "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50 "
        "\"float cropwindow\" [0.255 0.75 0.5 0]\n");
    EXPECT_EQ(loadScene(file_).film.crop, (PixelBounds{26, 75, 0, 25}));
}

TEST_F(PbrtCamera, SensorsOtherThanCie1931AreRefusedNamingTheLine) {
    EXPECT_EQ(importError("Camera \"perspective\"\nFilm \"rgb\"\n  \"string sensor\" "
                          "\"canon_eos_100d\"\n"),
              at(3) +
                  ": Film: sensor \"canon_eos_100d\" is not supported: lamina has pbrt-v4's "
                  "\"cie1931\" sensor only (the CIE 1931 observer), not its measured camera "
                  "curves; remove the parameter");
    EXPECT_THAT(importError("Film \"rgb\" \"float whitebalance\" 2700\n"),
                ::testing::StartsWith(at(1) + ": Film: whitebalance 2700"));
    EXPECT_THAT(importError("Film \"rgb\" \"float exposuretime\" 2\n"),
                ::testing::StartsWith(at(1) + ": "));
    EXPECT_THAT(importError("Camera \"perspective\" \"float shutterclose\" 0\n"),
                ::testing::StartsWith(at(1) + ": the camera's shutterclose must be later"));
}

TEST_F(PbrtCamera, OrthographicCameraWithItsScreenWindow) {
    // pbrt-v4's default window: the shorter axis [-1, 1]; a uniform scale of the camera
    // transform scales it into scene units.
    const ImportedScene s = import(
        "Scale 2 2 2\nLookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\"\n"
        "Film \"rgb\" \"integer xresolution\" 40 \"integer yresolution\" 20\n");
    EXPECT_EQ(s.scene["camera"], Json::parse(R"({"type": "orthographic", "position": [0, 0, -5],
        "look_at": [0, 0, -4], "up": [0, 1, 0], "screen_window": [-1, 1, -0.5, 0.5],
        "handedness": "left"})"));
    const ImportedScene w = import("Camera \"orthographic\" \"float screenwindow\" [-3 1 -2 2]\n");
    EXPECT_EQ(w.scene["camera"]["screen_window"], Json::parse("[-3, 1, -2, 2]"));
    EXPECT_EQ(loadScene(file_).camera.orthographic, true);
    EXPECT_EQ(importError("Camera \"orthographic\" \"float lensradius\" 0.1\n"),
              at(1) +
                  ": an orthographic camera with a lens (lensradius) is not supported: "
                  "remove lensradius for a sharp orthographic view");
    EXPECT_EQ(importError("Camera \"realistic\"\n"),
              at(1) + ": Camera \"realistic\": no \"string lensfile\"");
}

// Camera "realistic": its lens file, stop, focus and the film's diagonal, as lamina's realistic
// camera (which loads: the lens focuses at 5 m).
TEST_F(PbrtCamera, TheRealisticCameraKeepsItsLensSystem) {
    write("lens.dat", "# one thin biconvex element, f about 50 mm\n51 0.5 1.5 20\n-51 45 1 20\n");
    const ImportedScene s = import(
        "Camera \"realistic\" \"string lensfile\" \"lens.dat\" \"float aperturediameter\" 8\n"
        "  \"float focusdistance\" 5\n"
        "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 48 \"float diagonal\" "
        "40\n");
    const Json& c = s.scene["camera"];
    EXPECT_EQ(c["type"], "realistic");
    EXPECT_EQ(c["lens_file"], "lens.dat");
    EXPECT_EQ(c["aperture_diameter"], 8.0);
    EXPECT_EQ(c["focus_distance"], 5.0);
    EXPECT_EQ(c["film_diagonal"], 40.0);
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_TRUE(loadScene(file_).camera.lensSystem);
}

}  // namespace
}  // namespace lamina::render
