// Motion blur (docs/scene-format.md, "Motion blur") against a closed form: a black square
// slides at constant speed across a row of pixels in front of an emitting plane of radiance
// 1, seen by an orthographic camera whose pixels are unit squares of the plane. A pixel's
// value is 1 minus the time average, over the shutter, of the fraction of the pixel the
// square covers: the analytic smear. Path tracing, light tracing and BDPT each render it
// (fixed seeds) and every pixel must be within 4 of its standard errors (+1e-3) of the smear;
// a shutter that opens and closes at once is the still image at that time, exactly.
// Breaking it once on purpose (every sample at the shutter's opening time instead of a time
// drawn over it) fails every pixel the square passes.
#include <gtest/gtest.h>

#include <algorithm>

#include "lamina/geometry/geometry.h"
#include "lamina/geometry/ray_time.h"
#include "lamina/render/renderer.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::sceneFromText;

// Pixel i (of 16) sees x in [i, i + 1] of the plane; the square is 2 wide and covers more than
// the row's height; its centre moves from x = 3 at time 0 to x = 11 at time 1.
std::string slidingSquare(double open, double close) {
    return R"({
      "camera": {"type": "orthographic", "position": [8, 0, -5], "look_at": [8, 0, 0],
                 "handedness": "left", "screen_window": [-8, 8, -0.5, 0.5],
                 "shutter": [)" +
           std::to_string(open) + ", " + std::to_string(close) + R"(]},
      "film": {"resolution": [16, 1]},
      "sampler": {"spp": 4096, "seed": 3},
      "objects": {"square": [{"type": "rectangle", "material": {"type": "lambert", "reflectance": 0},
                              "transform": [{"scale": [1, 2, 1]}]}]},
      "shapes": [
        {"type": "instance", "object": "square", "transform": [{"translate": [3, 0, 0]}],
         "transform_end": [{"translate": [11, 0, 0]}]},
        {"type": "rectangle", "material": {"type": "lambert", "reflectance": 0},
         "emission": {"radiance": 1},
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"scale": [8.5, 1, 1]},
                       {"translate": [8, 0, 1]}]}]
    })";
}

// 1 - the time average of the covered fraction of pixel [i, i + 1] for a square [c - 1, c + 1]
// with c = 3 + 8 t, t uniform in [open, close]: the integrand is piecewise linear in t, so
// the midpoint rule with 2^16 steps is exact to ~1e-9.
double smear(int i, double open, double close) {
    const auto covered = [&](double t) {
        const double c = 3 + 8 * t;
        return std::clamp(std::min(double(i + 1), c + 1) - std::max(double(i), c - 1), 0.0, 1.0);
    };
    if (open == close) return 1 - covered(open);
    constexpr int kSteps = 1 << 16;
    double sum = 0;
    for (int k = 0; k < kSteps; ++k)
        sum += covered(open + (close - open) * (k + 0.5) / kSteps);
    return 1 - sum / kSteps;
}

TEST(MotionBlur, ASlidingSquareSmearsAsTheAnalyticFootprint) {
    for (const auto& [open, close] : {std::pair{0.0, 1.0}, std::pair{0.25, 0.6}}) {
        const SceneDesc scene = sceneFromText(slidingSquare(open, close));
        // The test can tell a blur from a still: some pixel is neither open nor covered.
        double partial = 0;
        for (int i = 0; i < 16; ++i)
            partial = std::max(partial, std::min(smear(i, open, close), 1 - smear(i, open, close)));
        ASSERT_GT(partial, 0.2);
        for (const IntegratorKind k :
             {IntegratorKind::Path, IntegratorKind::Light, IntegratorKind::Bdpt}) {
            RenderOptions o;
            o.integrator = k;
            const RenderResult r = renderScene(scene, o);
            for (int i = 0; i < 16; ++i) {
                const double expected = smear(i, open, close);
                const double sigma = std::sqrt(r.film->varianceOfMean(i, 0));
                EXPECT_NEAR(r.film->pixel(i, 0)[1], expected, 4 * sigma + 1e-3)
                    << "pixel " << i << ", integrator " << int(k) << ", shutter [" << open << ", "
                    << close << "]";
            }
        }
    }
}

TEST(MotionBlur, AShutterOfNoDurationIsTheStillImageAtItsTime) {
    const SceneDesc scene = sceneFromText(slidingSquare(0.5, 0.5));
    const RenderResult r = renderScene(scene, RenderOptions{});
    // The square covers [6, 8] at time 0.5: pixels 6 and 7 are black, the others open.
    for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(r.film->pixel(i, 0)[1], i == 6 || i == 7 ? 0.0 : 1.0, 1e-6) << i;
}

// The hit on a moving instance is rebuilt with the transform at the ray's time: the square's
// centre is at x = 3 + 8 t, so a ray along z at x = 7.5 meets it from t = 0.4375 to 0.6875,
// at the point it aims at, and passes it before and after.
TEST(MotionBlur, AHitOnAMovingInstanceIsWhereTheInstanceStandsAtTheRaysTime) {
    const SceneDesc scene = sceneFromText(slidingSquare(0, 1));
    const Geometry geometry(scene);
    const auto hitAt = [&](float time) {
        const RayTimeScope scope(time);
        return geometry.intersect({7.5f, 0.25f, -5.0f}, {0.0f, 0.0f, 1.0f});
    };
    for (const float time : {0.45f, 0.55f, 0.65f}) {
        const auto hit = hitAt(time);
        ASSERT_TRUE(hit) << time;
        EXPECT_EQ(hit->instance, 0) << time;
        EXPECT_NEAR(hit->p.x, 7.5f, 1e-5f);
        EXPECT_NEAR(hit->p.y, 0.25f, 1e-5f);
        EXPECT_NEAR(hit->p.z, 0.0f, 1e-5f);
        EXPECT_NEAR(hit->t, 5.0f, 1e-5f);
    }
    for (const float time : {0.0f, 0.4f, 0.72f, 1.0f}) {
        const auto hit = hitAt(time);
        ASSERT_TRUE(hit) << time;
        EXPECT_EQ(hit->instance, -1) << time;  // the emitter behind
    }
    EXPECT_EQ(currentRayTime(), 0.0f);  // the scopes restored it
}

TEST(MotionBlur, AStaticSceneDrawsNoTime) {
    SceneDesc scene = sceneFromText(slidingSquare(0, 1));
    EXPECT_TRUE(scene.hasMotion());
    scene.instances[0].toWorldEnd.reset();
    EXPECT_FALSE(scene.hasMotion());
}

TEST(MotionBlur, AMotionThroughAFlatMatrixIsRefused) {
    const std::string error = lamina::testing::errorOf([] {
        sceneFromText(R"({
          "objects": {"o": [{"type": "sphere", "material": {"type": "lambert"}}]},
          "shapes": [{"type": "instance", "object": "o",
                      "transform_end": [{"rotate": {"axis": [0, 0, 1], "angle": 180}}]}],
          "lights": [{"type": "point", "intensity": 1}]})");
    });
    EXPECT_NE(error.find("<test scene>: shapes[0].transform_end: the motion from transform to "
                         "transform_end passes through a flat (singular) matrix"),
              std::string::npos)
        << error;
    EXPECT_EQ(lamina::testing::errorOf([] {
                  sceneFromText(R"({"camera": {"shutter": [1, 0]},
                                   "lights": [{"type": "point", "intensity": 1}]})");
              }),
              "<test scene>: camera.shutter: expected [open, close] with open <= close");
}

}  // namespace
}  // namespace lamina::render
