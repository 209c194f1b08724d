// The film's sensor (film_response.h) and crop against closed forms: an imaging ratio of 2
// doubles every pixel exactly; the white balance maps the white of daylight at its temperature
// to neutral (and a spectral render of that daylight comes out grey); the clamp bounds every
// pixel's largest CIE XYZ component; a crop holds exactly the pixels of the full render there.
#include <gtest/gtest.h>

#include <algorithm>

#include "lamina/render/film_response.h"
#include "lamina/scene/scene_description.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/white_balance.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::kOneEmitterOfEveryKind;
using lamina::testing::sceneFromText;

RenderResult renderWith(const SceneDesc& scene, IntegratorKind integrator, RenderModeKind mode) {
    RenderOptions o;
    o.integrator = integrator;
    o.mode = mode;
    o.spp = 4;
    o.seed = 3;
    o.threads = 1;  // splats in one order: the images are compared bit for bit
    return renderScene(scene, o);
}

class FilmSensorModes
    : public ::testing::TestWithParam<std::tuple<IntegratorKind, RenderModeKind>> {};

TEST_P(FilmSensorModes, AnImagingRatioOfTwoDoublesTheImageExactly) {
    const auto [integrator, mode] = GetParam();
    SceneDesc scene = sceneFromText(kOneEmitterOfEveryKind);
    const RenderResult a = renderWith(scene, integrator, mode);
    scene.film.iso = 400;
    scene.film.exposureTime = 0.5;  // 0.5 s x ISO 400 / 100 = 2
    const RenderResult b = renderWith(scene, integrator, mode);
    double largest = 0;
    for (int y = 0; y < a.film->height(); ++y)
        for (int x = 0; x < a.film->width(); ++x)
            for (int c = 0; c < 3; ++c) {
                // Scaling by 2 commutes with every rounding: the doubles are exact.
                ASSERT_EQ(b.film->pixel(x, y)[c], 2 * a.film->pixel(x, y)[c]) << x << ", " << y;
                largest = std::max(largest, a.film->pixel(x, y)[c]);
            }
    EXPECT_GT(largest, 0.0);
}

// A crop renders the pixels of the full render: the path integrator's samples depend only on
// the pixel, light tracing's and BDPT's particles are traced from every pixel as in the full
// render (one thread: in the same order).
TEST_P(FilmSensorModes, ACropHoldsThePixelsOfTheFullRender) {
    const auto [integrator, mode] = GetParam();
    SceneDesc scene = sceneFromText(kOneEmitterOfEveryKind);
    const RenderResult full = renderWith(scene, integrator, mode);
    scene.film.crop = PixelBounds{2, 7, 3, 8};
    const RenderResult crop = renderWith(scene, integrator, mode);
    ASSERT_EQ(crop.film->width(), 5);
    ASSERT_EQ(crop.film->height(), 5);
    EXPECT_EQ(crop.film->window(), *scene.film.crop);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(crop.film->pixel(x, y)[c], full.film->pixel(x + 2, y + 3)[c]);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, FilmSensorModes,
    ::testing::Combine(::testing::Values(IntegratorKind::Path, IntegratorKind::Light,
                                         IntegratorKind::Bdpt),
                       ::testing::Values(RenderModeKind::Rgb, RenderModeKind::Spectral)));

TEST(FilmSensor, TheClampBoundsEveryPixelsLargestXyzComponent) {
    // The path integrator: every pixel is a weighted mean of clamped samples (box filter).
    const RgbColorSpace& rec709 = RgbColorSpace::rec709();
    for (const RenderModeKind mode : {RenderModeKind::Rgb, RenderModeKind::Spectral}) {
        SceneDesc scene = sceneFromText(kOneEmitterOfEveryKind);
        const auto largest = [&](const RenderResult& r) {
            double m = 0;
            for (int y = 0; y < r.film->height(); ++y)
                for (int x = 0; x < r.film->width(); ++x) {
                    const Rgb<double> p = r.film->pixel(x, y);
                    const Vec3d xyz = rec709.toXyz(Vec3d(p[0], p[1], p[2]));
                    m = std::max({m, xyz.x, xyz.y, xyz.z});
                }
            return m;
        };
        const double unclamped = largest(renderWith(scene, IntegratorKind::Path, mode));
        scene.film.maxComponentValue = 0.3;
        ASSERT_GT(unclamped, 0.5);  // the clamp has work to do
        EXPECT_LE(largest(renderWith(scene, IntegratorKind::Path, mode)), 0.3 * (1 + 1e-12));
    }
}

TEST(FilmSensor, WhiteBalanceMapsTheDaylightWhiteToNeutral) {
    const RgbColorSpace& rec709 = RgbColorSpace::rec709();
    for (const double kelvin : {4000.0, 5000.0, 6500.0, 9000.0, 25000.0}) {
        FilmDesc desc;
        desc.whiteBalance = kelvin;
        const Vec3d white = daylightChromaticity(kelvin).toXyz(0.7);
        // In spectral mode's film space (XYZ) and in RGB mode's (Rec.709).
        const Rgb<double> xyz =
            FilmResponse(desc, FilmSpace::Xyz).apply(Rgb<double>(white.x, white.y, white.z));
        const Vec3d fromXyz = rec709.toRgb(Vec3d(xyz[0], xyz[1], xyz[2]));
        const Vec3d rgbWhite = rec709.toRgb(white);
        const Rgb<double> rgb = FilmResponse(desc, FilmSpace::Rec709)
                                    .apply(Rgb<double>(rgbWhite.x, rgbWhite.y, rgbWhite.z));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(fromXyz[c], 0.7, 1e-12) << kelvin << " K";
            EXPECT_NEAR(rgb[c], 0.7, 1e-12) << kelvin << " K";
        }
        // Unbalanced, the same white is far from grey away from D65.
        if (kelvin != 6500) {
            EXPECT_GT(std::abs(rgbWhite.x / rgbWhite.z - 1), 0.05) << kelvin;
        }
    }
    // The locus at the D illuminants' nominal temperatures is their chromaticity (CIE 15:2004:
    // D50 (0.3457, 0.3585), D65 (0.3127, 0.3290)).
    EXPECT_NEAR(daylightChromaticity(5000).x, 0.3457, 2e-4);
    EXPECT_NEAR(daylightChromaticity(5000).y, 0.3585, 2e-4);
    EXPECT_NEAR(daylightChromaticity(6500).x, 0.3127, 2e-4);
    EXPECT_NEAR(daylightChromaticity(6500).y, 0.3290, 2e-4);
}

// Spectral mode integrates the D50 spectrum seen directly; balanced at 5000 K it is grey to the
// precision of the D50 table against the daylight locus and the spectral noise (4096 hero
// paths of four wavelengths per channel mean: about 0.1%), unbalanced it is yellowish.
TEST(FilmSensor, ASpectralRenderOfD50BalancedAt5000KelvinIsGrey) {
    const std::string text = R"({
      "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 20},
      "film": {"resolution": [16, 16]FILM},
      "sampler": {"type": "independent", "spp": 16},
      "shapes": [{"type": "rectangle", "material": {"type": "lambert", "reflectance": 0},
                  "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}],
                  "emission": {"radiance": {"illuminant": "D50", "scale": 1}}}]
    })";
    const auto mean = [&](const std::string& film) {
        std::string t = text;
        t.replace(t.find("FILM"), 4, film);
        RenderOptions o;
        o.mode = RenderModeKind::Spectral;
        const RenderResult r = renderScene(sceneFromText(t), o);
        Rgb<double> sum(0.0);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                sum += r.film->pixel(x, y);
        return sum / 256.0;
    };
    const Rgb<double> balanced = mean(R"(, "white_balance": 5000)");
    EXPECT_NEAR(balanced[0] / balanced[1], 1.0, 0.01);
    EXPECT_NEAR(balanced[2] / balanced[1], 1.0, 0.01);
    const Rgb<double> raw = mean("");
    EXPECT_GT(raw[0] / raw[2], 1.2);
}

TEST(FilmSensor, BadSensorAndCropKeysAreOneLineErrors) {
    const auto error = [](const std::string& film) {
        return lamina::testing::errorOf([&] {
            sceneFromText(R"({"film": {"resolution": [8, 4], )" + film +
                          R"(}, "lights": [{"type": "point", "intensity": 1}]})");
        });
    };
    EXPECT_EQ(error(R"("white_balance": 3000)"),
              "<test scene>: film.white_balance: expected 0 (none) or a colour temperature in "
              "[4000, 25000] kelvin (the CIE daylight locus)");
    EXPECT_EQ(error(R"("crop": [0, 9, 0, 4])"),
              "<test scene>: film.crop: expected 0 <= X0 < X1 <= 8 and 0 <= Y0 < Y1 <= 4 (the "
              "resolution)");
    EXPECT_EQ(error(R"("crop": [2, 2, 0, 4])"),
              "<test scene>: film.crop: expected 0 <= X0 < X1 <= 8 and 0 <= Y0 < Y1 <= 4 (the "
              "resolution)");
    EXPECT_NE(error(R"("max_component_value": 0)").find("film.max_component_value"),
              std::string::npos);
}

}  // namespace
}  // namespace lamina::render
