// The "media" of a scene file (docs/media.md): what the reader keeps, and one clean error
// naming the JSON path for every bad value; the renderers that do not render media yet refuse
// a scene with media in one line.
#include <gtest/gtest.h>

#include "lamina/core/error.h"
#include "lamina/render/renderer.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

using testing::sceneFromText;

// A scene around `media` (the "media" object), `shape` (extra keys of a unit sphere) and
// `camera` (extra camera keys).
std::string sceneWith(const std::string& media, const std::string& shape,
                      const std::string& camera = "") {
    return R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0])" +
           (camera.empty() ? "" : ", " + camera) + R"(},
      "media": )" +
           media + R"(,
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "sphere", )" +
           shape + R"(},
                 {"type": "rectangle", "material": "m", "emission": {"radiance": 1},
                  "transform": [{"translate": [0, 0, 3]}]}]})";
}

const char* kFog = R"({"fog": {"type": "homogeneous", "sigma_a": [0.1, 0.2, 0.3],
                               "sigma_s": 0.5, "scale": 2, "g": 0.4, "Le": [1, 2, 3]}})";

TEST(MediaReader, KeepsCoefficientsInterfacesAndTheCameraMedium) {
    const SceneDesc s = sceneFromText(
        sceneWith(kFog, R"("material": "interface", "interior": "fog")", R"("medium": "vacuum")"));
    ASSERT_EQ(s.media.size(), 1u);
    const MediumDesc& m = s.media[0];
    EXPECT_EQ(m.name, "fog");
    // sigma times scale
    EXPECT_DOUBLE_EQ(m.sigmaA[0], 0.2);
    EXPECT_DOUBLE_EQ(m.sigmaA[2], 0.6);
    EXPECT_DOUBLE_EQ(m.sigmaS[1], 1.0);
    EXPECT_DOUBLE_EQ(m.g, 0.4);
    EXPECT_DOUBLE_EQ(m.emission[2], 3.0);  // Le is not scaled
    EXPECT_TRUE(m.emits());
    EXPECT_EQ(s.camera.medium, -1);
    const SurfaceDesc* sphere = nullptr;
    for (const ShapeDesc& shape : s.shapes)
        if (std::holds_alternative<SphereDesc>(shape)) sphere = &surface(shape);
    ASSERT_NE(sphere, nullptr);
    EXPECT_TRUE(sphere->isInterface());
    ASSERT_TRUE(sphere->media.has_value());
    EXPECT_EQ(sphere->media->interior, 0);
    EXPECT_EQ(sphere->media->exterior, -1);  // absent: vacuum
    EXPECT_TRUE(s.hasMedia());
}

TEST(MediaReader, CameraMediumAndMaterialsWithMedia) {
    const SceneDesc s = sceneFromText(
        sceneWith(kFog, R"("material": "m", "exterior": "fog")", R"("medium": "fog")"));
    EXPECT_EQ(s.camera.medium, 0);
    for (const ShapeDesc& shape : s.shapes)
        if (std::holds_alternative<SphereDesc>(shape)) {
            EXPECT_FALSE(surface(shape).isInterface());
            EXPECT_EQ(surface(shape).media->exterior, 0);
            EXPECT_EQ(surface(shape).media->interior, -1);
        }
    // Grey defaults: no absorption, no scattering, isotropic, no emission.
    const SceneDesc d =
        sceneFromText(sceneWith(R"({"clear": {"type": "homogeneous"}})", R"("material": "m")"));
    EXPECT_EQ(d.media[0].sigmaA.maxValue(), 0.0);
    EXPECT_EQ(d.media[0].g, 0.0);
    EXPECT_FALSE(d.media[0].emits());
}

TEST(MediaReader, SceneWithoutMediaHasNone) {
    const SceneDesc s = sceneFromText(sceneWith("{}", R"("material": "m")"));
    EXPECT_FALSE(s.hasMedia());
}

// Each bad input: the message names the JSON path and what was expected.
struct BadMedium {
    const char* name;
    std::string scene;
    const char* expected;  ///< a part of the message
};

std::vector<BadMedium> badMedia() {
    return {
        {"unknown_interior", sceneWith(kFog, R"("material": "m", "interior": "smoke")"),
         "shapes[0].interior: unknown medium \"smoke\"; defined: fog"},
        {"unknown_camera_medium", sceneWith(kFog, R"("material": "m")", R"("medium": "smoke")"),
         "camera.medium: unknown medium \"smoke\""},
        {"negative_sigma",
         sceneWith(R"({"f": {"type": "homogeneous", "sigma_a": [0.1, -1, 0]}})",
                   R"("material": "m")"),
         "media.f.sigma_a"},
        {"g_one", sceneWith(R"({"f": {"type": "homogeneous", "g": 1}})", R"("material": "m")"),
         "media.f.g"},
        {"g_minus_one",
         sceneWith(R"({"f": {"type": "homogeneous", "g": -1}})", R"("material": "m")"),
         "media.f.g"},
        {"nan_sigma",
         sceneWith(R"({"f": {"type": "homogeneous", "sigma_s": "nan"}})", R"("material": "m")"),
         "media.f.sigma_s"},
        {"infinite_sigma",
         sceneWith(R"({"f": {"type": "homogeneous", "sigma_s": 1e300}})", R"("material": "m")"),
         "media.f.sigma_s"},
        {"overflowing_scale",
         sceneWith(R"({"f": {"type": "homogeneous", "sigma_s": 1e30, "scale": 1e30}})",
                   R"("material": "m")"),
         "media.f.sigma_s: times scale"},
        {"unknown_type", sceneWith(R"({"f": {"type": "smoke"}})", R"("material": "m")"),
         "media.f.type: expected one of homogeneous, grid, cloud"},
        {"unknown_key",
         sceneWith(R"({"f": {"type": "homogeneous", "sigma_t": 1}})", R"("material": "m")"),
         "sigma_t"},
        {"vacuum_named", sceneWith(R"({"vacuum": {"type": "homogeneous"}})", R"("material": "m")"),
         "media.vacuum"},
        {"interface_without_media", sceneWith(kFog, R"("material": "interface")"),
         "shapes[0].material: an \"interface\" shape needs \"interior\" or \"exterior\""},
        {"emitting_interface",
         sceneWith(kFog,
                   R"("material": "interface", "interior": "fog", "emission": {"radiance": 1})"),
         "shapes[0].emission: an \"interface\" shape does not emit"},
    };
}

class MediaReaderRefuses : public ::testing::TestWithParam<BadMedium> {};

TEST_P(MediaReaderRefuses, WithThePathAndWhatWasExpected) {
    try {
        sceneFromText(GetParam().scene);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(BadValues, MediaReaderRefuses, ::testing::ValuesIn(badMedia()),
                         [](const ::testing::TestParamInfo<BadMedium>& p) { return p.param.name; });

TEST(MediaReader, RefusesAMaterialNamedInterface) {
    const std::string scene = R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "materials": {"interface": {"type": "lambert"}},
      "shapes": [{"type": "sphere", "material": "interface", "emission": {"radiance": 1}}]})";
    try {
        sceneFromText(scene);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("materials.interface"), std::string::npos) << e.what();
    }
}

// Light tracing and BDPT of an emitting medium that fills space and the polarised mode refuse
// media in one line, never render them as vacuum; light tracing and BDPT render the others,
// emitting media enclosed by shapes included.
TEST(MediaReader, RenderersWithoutMediaRefuseThem) {
    const SceneDesc s = sceneFromText(sceneWith(kFog, R"("material": "m")", R"("medium": "fog")"));
    EXPECT_NO_THROW(checkMedia(s, RenderModeKind::Spectral, IntegratorKind::Path));
    // kFog emits (Le) and is the camera's medium, bounded by no shape: light tracing and BDPT
    // cannot sample its volume and refuse it; they take the same fog without emission, and
    // the emitting fog inside a sphere.
    for (const IntegratorKind integrator : {IntegratorKind::Light, IntegratorKind::Bdpt}) {
        try {
            checkMedia(s, RenderModeKind::Spectral, integrator);
            ADD_FAILURE() << kIntegratorNames.name(integrator) << " accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "<test scene>: media.fog.Le: the light and bdpt integrators start "
                      "particles in an emitting medium's volume, and this one reaches infinity "
                      "(no shapes enclose it); enclose it with shapes or use --integrator path");
        }
    }
    const SceneDesc enclosed =
        sceneFromText(sceneWith(kFog, R"("material": "interface", "interior": "fog")"));
    EXPECT_NO_THROW(checkMedia(enclosed, RenderModeKind::Spectral, IntegratorKind::Light));
    EXPECT_NO_THROW(checkMedia(enclosed, RenderModeKind::Rgb, IntegratorKind::Bdpt));
    // Outside a sphere, around the camera: bounded by a shape, but reaching infinity, which
    // only the geometry tells: refused when the integrator is made, before anything renders.
    const SceneDesc outside = sceneFromText(
        sceneWith(kFog, R"("material": "interface", "exterior": "fog")", R"("medium": "fog")"));
    EXPECT_NO_THROW(checkMedia(outside, RenderModeKind::Rgb, IntegratorKind::Bdpt));
    for (const IntegratorKind integrator : {IntegratorKind::Light, IntegratorKind::Bdpt}) {
        RenderOptions o;
        o.integrator = integrator;
        o.spp = 1;
        try {
            renderScene(outside, o);
            ADD_FAILURE() << kIntegratorNames.name(integrator) << " rendered";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("<test scene>: media.fog.Le: the light and bdpt "
                                                 "integrators start particles"),
                      std::string::npos)
                << e.what();
        }
    }
    const SceneDesc dark = sceneFromText(
        sceneWith(R"({"fog": {"type": "homogeneous", "sigma_a": 0.1, "sigma_s": 0.5}})",
                  R"("material": "m")", R"("medium": "fog")"));
    EXPECT_NO_THROW(checkMedia(dark, RenderModeKind::Rgb, IntegratorKind::Light));
    EXPECT_NO_THROW(checkMedia(dark, RenderModeKind::Spectral, IntegratorKind::Light));
    EXPECT_NO_THROW(checkMedia(dark, RenderModeKind::Rgb, IntegratorKind::Bdpt));
    EXPECT_NO_THROW(checkMedia(dark, RenderModeKind::Spectral, IntegratorKind::Bdpt));
    EXPECT_THROW(checkMedia(dark, RenderModeKind::Polarised, IntegratorKind::Bdpt), InputError);
    EXPECT_THROW(checkMedia(s, RenderModeKind::Polarised, IntegratorKind::Path), InputError);
    RenderOptions o;
    o.integrator = IntegratorKind::Bdpt;
    o.spp = 1;
    EXPECT_THROW(renderScene(s, o), InputError);
    const SceneDesc vacuum = sceneFromText(sceneWith("{}", R"("material": "m")"));
    EXPECT_NO_THROW(checkMedia(vacuum, RenderModeKind::Polarised, IntegratorKind::Bdpt));
}

}  // namespace
}  // namespace lamina::render
