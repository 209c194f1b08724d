// The two ends of a light path: the lights' emission sampling (light tracing, BDPT) and the
// camera's importance. Each light's particles must carry its power on average,
//   E[ Le |cos| / (pdfPosition pdfDirection) ] = power(),
// with the densities emissionPdf() reports; the camera's importance must integrate to the film
// area in pixels, its ray density to 1, and rasterPosition must invert generateRay.
#include <gtest/gtest.h>

#include "lamina/core/pcg32.h"
#include "lamina/lights/lights.h"
#include "lamina/render/camera.h"
#include "lamina/render/perspective_camera.h"
#include "lamina/spectral/color_space.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

TEST(EmissionSampling, ParticlesCarryEachLightsPowerWithTheReportedDensities) {
    const SceneDesc scene = testing::sceneFromText(testing::kOneEmitterOfEveryKind);
    Geometry geometry(scene);
    const LightSet lights(scene, geometry, render::LightSelection::Power);
    ASSERT_EQ(lights.size(), 9u);
    constexpr int kSamples = 400000;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights.light(i);
        Pcg32 rng(17 + i);
        double sum = 0, sumSq = 0;
        int pdfMismatches = 0;
        for (int k = 0; k < kSamples; ++k) {
            const Vec2f u1(rng.nextFloat(), rng.nextFloat()), u2(rng.nextFloat(), rng.nextFloat());
            const auto e = light.sampleEmission(u1, u2);
            if (!e) continue;
            ASSERT_GT(e->pdfPosition, 0.0f) << i;
            ASSERT_GT(e->pdfDirection, 0.0f) << i;
            const double v = luminance(Rgb<double>(e->radiance.rgb())) *
                             std::abs(glm::dot(e->normal, e->direction)) /
                             (double(e->pdfPosition) * double(e->pdfDirection));
            sum += v;
            sumSq += v * v;
            const EmissionPdf p = light.emissionPdf(e->point, e->normal, e->direction);
            if (std::abs(p.position / e->pdfPosition - 1) > 1e-4 ||
                std::abs(p.direction / e->pdfDirection - 1) > 1e-4)
                ++pdfMismatches;
        }
        const double mean = sum / kSamples;
        const double se = std::sqrt(std::max(0.0, sumSq / kSamples - mean * mean) / kSamples);
        // 4 standard errors (and float round-off) for each of 9 lights.
        EXPECT_NEAR(mean, light.power(), 4 * se + 1e-5 * light.power()) << "light " << i;
        EXPECT_EQ(pdfMismatches, 0) << "light " << i;
    }
}

CameraDesc cameraDesc(double aperture) {
    CameraDesc d;
    d.position = Vec3<double>(0.5, 1, -3);
    d.lookAt = Vec3<double>(0, 0.2, 0);
    d.up = Vec3<double>(0, 1, 0);
    d.verticalFovDegrees = 40;
    d.apertureRadius = aperture;
    d.focusDistance = 3;
    return d;
}

class CameraImportance : public ::testing::TestWithParam<double> {};

TEST_P(CameraImportance, RasterPositionInvertsGenerateRay) {
    const PerspectiveCamera camera(cameraDesc(GetParam()), 64, 48);
    Pcg32 rng(3);
    for (int k = 0; k < 1000; ++k) {
        const float x = 64 * rng.nextFloat(), y = 48 * rng.nextFloat();
        const auto ray = camera.generateRay(x, y, Vec2f(rng.nextFloat(), rng.nextFloat()));
        const auto raster = camera.rasterPosition(ray.origin, ray.direction);
        ASSERT_TRUE(raster.has_value());
        EXPECT_NEAR(raster->x, x, 2e-3f);
        EXPECT_NEAR(raster->y, y, 2e-3f);
    }
}

TEST_P(CameraImportance, ImportanceIntegratesToTheFilmAreaAndRayDensityToOne) {
    // Over the directions leaving one lens point: integral of We cos A_lens = W x H pixels,
    // integral of the ray direction density = 1 (uniform directions, 2M samples).
    const PerspectiveCamera camera(cameraDesc(GetParam()), 64, 48);
    const double lensArea = GetParam() > 0 ? kPi<double> * sqr(GetParam()) : 1.0;
    const Vec3f lens = camera.generateRay(32, 24, Vec2f(0.3f, 0.8f)).origin;
    Pcg32 rng(5);
    constexpr int kSamples = 2000000;
    double we = 0, pdf = 0;
    for (int k = 0; k < kSamples; ++k) {
        const Vec3f d = squareToUniformSphere(Vec2f(rng.nextFloat(), rng.nextFloat()));
        if (!camera.rasterPosition(lens, d)) continue;
        const double c = glm::dot(d, camera.forward());
        we += camera.importance(d) * c * lensArea / uniformSpherePdf<double>();
        pdf += camera.rayPdf(d).direction / uniformSpherePdf<double>();
    }
    EXPECT_NEAR(we / kSamples / (64.0 * 48.0), 1.0, 0.01);
    EXPECT_NEAR(pdf / kSamples, 1.0, 0.01);
}

TEST_P(CameraImportance, ConnectionsLandWhereTheRayThroughThemStarts) {
    const PerspectiveCamera camera(cameraDesc(GetParam()), 64, 48);
    Pcg32 rng(9);
    for (int k = 0; k < 200; ++k) {
        const auto ray = camera.generateRay(64 * rng.nextFloat(), 48 * rng.nextFloat(),
                                            Vec2f(rng.nextFloat(), rng.nextFloat()));
        const Vec3f p = ray.origin + (2.0f + 3.0f * rng.nextFloat()) * ray.direction;
        const auto c = camera.sampleConnection(p, Vec2f(rng.nextFloat(), rng.nextFloat()));
        if (!c) continue;  // a lens point from which p is off the film
        const auto raster = camera.rasterPosition(c->lensPoint, -c->wi);
        ASSERT_TRUE(raster.has_value());
        EXPECT_NEAR(raster->x, c->raster.x, 1e-3f);
        EXPECT_NEAR(glm::length(c->lensPoint - p), c->distance, 1e-4f);
    }
}

INSTANTIATE_TEST_SUITE_P(PinholeAndThinLens, CameraImportance, ::testing::Values(0.0, 0.1));

}  // namespace
}  // namespace lamina::render
