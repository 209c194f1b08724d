// Emitting quadrics (QuadricLight, area_lights.h): sampled uniformly by area over the clipped
// surface only. From a point that sees each direction's hit at most once, the directions
// next-event estimation draws must follow the density pdf() reports for the hit a ray along
// them finds (chi-square over the sphere of directions, Mitsuba 3's test), and that density
// must integrate to 1, which holds only with the closed-form area; every sample's density
// converted to area is 1 / area; the particles carry the light's power pi A L (two-sided:
// 2 pi A L). Four shapes at a family-wise significance of 1% (Sidak); the power by a z-test
// at 4 standard errors.
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/lights/lights.h"
#include "lamina/spectral/color_space.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

struct QuadricCase {
    const char* name;
    const char* shape;  ///< the emitting shape's JSON keys, material and emission aside
    Vec3f ref;          ///< sees every direction's hit once at most, and the front side
    double area;        ///< the closed form
    bool twoSided = false;
};

constexpr double kPiD = kPi<double>;

const QuadricCase kCases[] = {
    // A cap of the unit sphere above z = 0.3, three quarters round, facing its centre.
    {"SphereCapFromItsCentre",
     R"("type": "sphere", "z_min": 0.3, "phi_max": 270, "flip_normals": true,
        "transform": [{"rotate": {"axis": [1, 1, 0], "angle": 30}}, {"translate": [0.5, 0, 0]}])",
     {0.5f, 0.0f, 0.0f},
     1.5 * kPiD * 1 * 0.7},
    // Five sixths of a cylinder of radius 1, z in [-1, 2], facing its axis, seen from it.
    {"CylinderFromItsAxis",
     R"("type": "cylinder", "z_min": -1, "z_max": 2, "phi_max": 300, "flip_normals": true)",
     {0.0f, 0.0f, 0.2f},
     5.0 / 3.0 * kPiD * 3},
    // A whole cylinder, two-sided, scaled.
    {"WholeTwoSidedCylinder",
     R"("type": "cylinder", "radius": 0.5, "z_min": 0, "z_max": 2, "transform": [{"scale": 2}])",
     {0.0f, 0.0f, 1.0f},
     2 * kPiD * 1 * 4,
     true},
    // A sector of an annulus, radius 2 and 0.5, 200 degrees, from above its plane.
    {"AnnulusSectorFromAbove",
     R"("type": "disk", "radius": 2, "inner_radius": 0.5, "phi_max": 200,
        "transform": [{"translate": [0, 0, -1]}])",
     {0.3f, -0.2f, 0.5f},
     200.0 / 360.0 * kPiD*(4 - 0.25)}};

SceneDesc sceneOf(const QuadricCase& c) {
    return testing::sceneFromText(
        std::string(R"({"materials": {"m": {"type": "lambert", "reflectance": 0.5}},
        "shapes": [{"material": "m", "emission": {"radiance": [1, 2, 3], "two_sided": )") +
        (c.twoSided ? "true" : "false") + "}, " + c.shape + "}]}");
}

class QuadricLightSampling : public ::testing::TestWithParam<QuadricCase> {};

TEST_P(QuadricLightSampling, DirectionsFollowTheReportedDensityWhichIntegratesToOne) {
    const QuadricCase& c = GetParam();
    const SceneDesc scene = sceneOf(c);
    const Geometry geometry(scene);
    const LightSet lights(scene, geometry, LightSelection::Power);
    ASSERT_EQ(lights.size(), 1u);
    const Light& light = lights.light(0);
    ChiSquareConfig config;
    config.significance = testing::kSignificance;
    config.testCount = int(std::size(kCases));
    config.seed = 23;
    const auto sampler = [&](Pcg32& rng) -> std::optional<Vec3d> {
        const auto s = light.sample(c.ref, Vec2f(rng.nextFloat(), rng.nextFloat()));
        if (!s) return std::nullopt;
        return Vec3d(s->wi);
    };
    const auto pdf = [&](const Vec3d& w) {
        const auto hit = geometry.intersect(c.ref, Vec3f(w));
        return hit ? double(light.pdf(c.ref, *hit)) : 0.0;
    };
    const ChiSquareResult r = runChiSquareTest(config, sampler, pdf);
    EXPECT_TRUE(testing::passes(r));
    // The density of uniform sampling by area, dist^2 / (|cos| A), integrates over the
    // directions that see the shape to its true area over the A it is divided by: estimated
    // over uniform directions (2 million), within 4 standard errors of 1.
    Pcg32 rng(31);
    constexpr int kDirections = 2000000;
    double sum = 0, sumSq = 0;
    for (int k = 0; k < kDirections; ++k) {
        const double v =
            pdf(Vec3d(squareToUniformSphere(Vec2f(rng.nextFloat(), rng.nextFloat())))) /
            uniformSpherePdf<double>();
        sum += v;
        sumSq += v * v;
    }
    const double mean = sum / kDirections;
    const double se = std::sqrt((sumSq / kDirections - mean * mean) / kDirections);
    EXPECT_NEAR(mean, 1.0, 4 * se) << c.name << ": the quadrature's integral " << r.pdfIntegral;
    std::printf("  %-24s integral of the density %.5f +- %.5f (quadrature %.5f), p %.3f\n", c.name,
                mean, se, r.pdfIntegral, r.pValue);
}

TEST_P(QuadricLightSampling, EachSamplesDensityByAreaIsOneOverTheClosedFormArea) {
    const QuadricCase& c = GetParam();
    const SceneDesc scene = sceneOf(c);
    EXPECT_NEAR(std::get<QuadricDesc>(scene.shapes[0]).area(), c.area, 1e-12 * c.area);
    const Geometry geometry(scene);
    const LightSet lights(scene, geometry, LightSelection::Power);
    const Light& light = lights.light(0);
    // pi A L for a one-sided Lambertian emitter, twice that for a two-sided one.
    EXPECT_NEAR(light.power(),
                (c.twoSided ? 2 : 1) * kPiD * c.area * luminance(Rgb<double>(1, 2, 3)),
                1e-9 * light.power());
    Pcg32 rng(5);
    for (int k = 0; k < 10000; ++k) {
        const auto s = light.sample(c.ref, Vec2f(rng.nextFloat(), rng.nextFloat()));
        ASSERT_TRUE(s) << c.name;
        const Vec3f d = s->point - c.ref;
        const double cosLight = std::abs(glm::dot(s->normal, glm::normalize(d)));
        const double pdfArea = double(s->pdf) * cosLight / glm::dot(d, d);
        ASSERT_NEAR(1 / pdfArea, c.area, 2e-4 * c.area) << c.name << " sample " << k;
    }
}

TEST_P(QuadricLightSampling, ParticlesCarryThePowerWithTheReportedDensities) {
    const QuadricCase& c = GetParam();
    const SceneDesc scene = sceneOf(c);
    const Geometry geometry(scene);
    const LightSet lights(scene, geometry, LightSelection::Power);
    const Light& light = lights.light(0);
    constexpr int kSamples = 200000;
    Pcg32 rng(29);
    double sum = 0, sumSq = 0;
    for (int k = 0; k < kSamples; ++k) {
        const auto e = light.sampleEmission(Vec2f(rng.nextFloat(), rng.nextFloat()),
                                            Vec2f(rng.nextFloat(), rng.nextFloat()));
        if (!e) continue;
        const EmissionPdf p = light.emissionPdf(e->point, e->normal, e->direction);
        ASSERT_NEAR(p.position / e->pdfPosition, 1.0f, 1e-4f);
        ASSERT_NEAR(p.direction / e->pdfDirection, 1.0f, 1e-4f);
        // A particle leaves from the surface: a ray back along it hits the light there.
        const auto hit = geometry.intersect(e->point + 1e-3f * e->direction, -e->direction);
        ASSERT_TRUE(hit) << c.name;
        EXPECT_LT(glm::length(hit->p - e->point), 2e-3f) << c.name;
        const double v = luminance(Rgb<double>(e->radiance.rgb())) *
                         std::abs(glm::dot(e->normal, e->direction)) /
                         (double(e->pdfPosition) * double(e->pdfDirection));
        sum += v;
        sumSq += v * v;
    }
    const double mean = sum / kSamples;
    const double se = std::sqrt(std::max(0.0, sumSq / kSamples - mean * mean) / kSamples);
    EXPECT_NEAR(mean, light.power(), 4 * se + 1e-5 * light.power()) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Shapes, QuadricLightSampling, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace lamina::render
