// The orthographic camera (orthographic_camera.h) against closed forms: its rays leave the
// screen window along the view, a connection lands where the ray through it starts, an
// emitting plane seen orthographically is its radiance in every pixel (path tracing: exactly;
// light tracing and BDPT, whose importance K = W H / A carries it: within their noise), and a
// diffuse plane under a uniform sky is albedo x sky everywhere.
#include <gtest/gtest.h>

#include "lamina/core/pcg32.h"
#include "lamina/render/camera.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::sceneFromText;

CameraDesc orthographic(std::array<double, 4> window) {
    CameraDesc d;
    d.position = {1, 2, -5};
    d.lookAt = {1, 2, 0};
    d.orthographic = true;
    d.screenWindow = window;
    return d;
}

TEST(OrthographicCamera, RaysLeaveTheScreenWindowAlongTheView) {
    const Camera camera(orthographic({-3, 1, -0.5, 1.5}), 40, 20);
    EXPECT_TRUE(camera.isPinhole());
    EXPECT_TRUE(camera.parallel());
    // Right-handed: looking along +z with +y up, the image's right is -x.
    const CameraRay topLeft = camera.generateRay(0, 0, {0.5f, 0.5f});
    const CameraRay bottomRight = camera.generateRay(40, 20, {0.5f, 0.5f});
    EXPECT_NEAR(topLeft.origin.x, 1 + 3, 1e-6);
    EXPECT_NEAR(topLeft.origin.y, 2 + 1.5, 1e-6);
    EXPECT_NEAR(bottomRight.origin.x, 1 - 1, 1e-6);
    EXPECT_NEAR(bottomRight.origin.y, 2 - 0.5, 1e-6);
    EXPECT_NEAR(topLeft.origin.z, -5, 1e-6);
    EXPECT_EQ(topLeft.direction, Vec3f(0, 0, 1));
    EXPECT_EQ(bottomRight.direction, Vec3f(0, 0, 1));
    // The default window: the shorter axis [-1, 1].
    CameraDesc d = orthographic({});
    d.screenWindow.reset();
    const CameraRay corner = Camera(d, 40, 20).generateRay(0, 0, {});
    EXPECT_NEAR(corner.origin.x, 1 + 2, 1e-6);
    EXPECT_NEAR(corner.origin.y, 2 + 1, 1e-6);
}

TEST(OrthographicCamera, ConnectionsLandWhereTheRayThroughThemStarts) {
    const Camera camera(orthographic({-3, 1, -0.5, 1.5}), 40, 20);
    Pcg32 rng(5);
    for (int i = 0; i < 1000; ++i) {
        const float x = 40 * rng.nextFloat(), y = 20 * rng.nextFloat();
        const CameraRay ray = camera.generateRay(x, y, {});
        const float t = 0.1f + 10 * rng.nextFloat();
        const auto c = camera.sampleConnection(ray.origin + t * ray.direction, {});
        ASSERT_TRUE(c);
        EXPECT_NEAR(c->raster.x, x, 2e-3);
        EXPECT_NEAR(c->raster.y, y, 2e-3);
        EXPECT_NEAR(c->distance, t, 1e-4);
        EXPECT_EQ(c->wi, -ray.direction);
        // K = W H / A = 800 pixels / 8 square units.
        EXPECT_FLOAT_EQ(c->importance, 100.0f);
        EXPECT_EQ(c->pdf, 1.0f);
    }
    // Behind the film plane, or beside the window: no connection.
    EXPECT_FALSE(camera.sampleConnection({1, 2, -6}, {}));
    EXPECT_FALSE(camera.sampleConnection({10, 2, 3}, {}));
    // The density of a point reached by a ray: |cos| / A.
    EXPECT_FLOAT_EQ(camera.parallelPdf(glm::normalize(Vec3f(0, 1, -1)), true),
                    float(std::sqrt(0.5) / 8));
}

// A rectangle emitting radiance 1.5 towards the camera, larger than the screen window.
constexpr const char* kEmittingPlane = R"({
  "camera": {"type": "orthographic", "position": [0, 0, -3], "look_at": [0, 0, 0],
             "screen_window": [-1, 1, -0.75, 0.75]},
  "film": {"resolution": [16, 12]},
  "sampler": {"type": "independent", "spp": 64, "seed": 9},
  "shapes": [{"type": "rectangle", "material": {"type": "lambert", "reflectance": 0},
              "transform": [{"scale": 2}, {"rotate": {"axis": [0, 1, 0], "angle": 180}}],
              "emission": {"radiance": 1.5}}]
})";

TEST(OrthographicCamera, AnEmittingPlaneIsItsRadianceInEveryPixel) {
    const SceneDesc scene = sceneFromText(kEmittingPlane);
    RenderOptions o;
    const RenderResult path = renderScene(scene, o);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(path.film->pixel(x, y)[c], 1.5, 1e-6) << x << ", " << y;
    // Light tracing and BDPT reach the film through the importance: its mean is the radiance
    // within 4 standard errors (a two-sided 6e-5 test; fixed seed).
    for (const IntegratorKind k : {IntegratorKind::Light, IntegratorKind::Bdpt}) {
        o.integrator = k;
        const RenderResult r = renderScene(scene, o);
        const auto m = lamina::testing::imageMean(*r.film, 1);
        EXPECT_NEAR(m.mean, 1.5, 4 * m.standardError + 1e-9) << int(k);
        EXPECT_LT(m.standardError, 0.05) << int(k);
    }
}

// A diffuse plane of albedo 0.6 under a uniform sky of radiance 2 reflects 1.2 wherever it is
// seen (it sees only the sky). The path integrator leaves a constant sky to BSDF sampling,
// whose cosine-distributed lambert sample has weight 0.6 exactly: every sample is 1.2, so every
// pixel is 1.2 to float rounding, and none is black (the window's footprint lies on the plane).
TEST(OrthographicCamera, ADiffusePlaneUnderAUniformSkyHasTheSameRadianceEverywhere) {
    const SceneDesc scene = sceneFromText(R"({
      "camera": {"type": "orthographic", "position": [0, 3, -3], "look_at": [0, 0, 0]},
      "film": {"resolution": [16, 16]},
      "sampler": {"type": "independent", "spp": 16, "seed": 4},
      "shapes": [{"type": "rectangle", "material": {"type": "lambert", "reflectance": 0.6},
                  "transform": [{"scale": 10}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
      "lights": [{"type": "environment", "radiance": 2}]
    })");
    for (const RenderModeKind mode : {RenderModeKind::Rgb, RenderModeKind::Spectral}) {
        RenderOptions o;
        o.mode = mode;
        const RenderResult r = renderScene(scene, o);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                ASSERT_NEAR(r.film->pixel(x, y)[1], 1.2, mode == RenderModeKind::Rgb ? 1e-6 : 0.1)
                    << x << ", " << y;
        const auto m = lamina::testing::imageMean(*r.film, 1);
        EXPECT_NEAR(m.mean, 1.2, 4 * m.standardError + 1e-6);
    }
}

TEST(OrthographicCamera, ALensOrAFieldOfViewIsRefused) {
    const auto error = [](const std::string& camera) {
        return lamina::testing::errorOf([&] {
            sceneFromText(R"({"camera": {"type": "orthographic", )" + camera +
                          R"(}, "lights": [{"type": "point", "intensity": 1}]})");
        });
    };
    EXPECT_EQ(error(R"("fov": 30)"),
              "<test scene>: camera.fov: an orthographic camera has no lens and no field of view");
    EXPECT_EQ(error(R"("screen_window": [1, -1, 0, 1])"),
              "<test scene>: camera.screen_window: expected X0 < X1 and Y0 < Y1");
}

}  // namespace
}  // namespace lamina::render
