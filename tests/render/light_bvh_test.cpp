// The light BVH's distribution (light_bvh.h, LightSet's `bvh` selection) at shading points:
// choose() must draw each light with the probability probability() reports, exactly the
// value it returns with the light, and the probabilities of all lights must sum to 1. Scenes: one
// light of every kind (with a directional light, which takes the fixed share, and a constant
// environment, which next-event estimation leaves to BSDF sampling) and scenes/many-lights.json
// (1056 lights). Chi-square: 400 000 draws per point, cells with an
// expected count below 5 pooled, 8 points at a family-wise significance of 1% (Sidak).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/render/image_output.h"
#include "lamina/render/lights.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

namespace fs = std::filesystem;

struct ShadingPoint {
    Vec3f p, n;
};

const ShadingPoint kMixedPoints[] = {{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
                                     {{2.0f, 0.5f, -1.0f}, {-1.0f, 0.0f, 0.0f}},
                                     {{0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, 0.0f}},
                                     {{0.2f, 0.5f, 0.1f}, {0.0f, 0.0f, -1.0f}}};
const ShadingPoint kManyLightPoints[] = {{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
                                         {{5.0f, 0.0f, -3.0f}, {0.0f, 1.0f, 0.0f}},
                                         {{-2.5f, 2.0f, 1.0f}, {0.0f, 1.0f, 0.0f}},
                                         {{1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}}};
constexpr int kChiSquareTests = 8;

SceneDesc manyLights() {
    return loadScene(std::string(LAMINA_SOURCE_DIR) + "/scenes/many-lights.json");
}

/// Pearson's test of choose()'s frequencies at `at` against probability().
ChiSquareResult selectionChiSquare(const LightSet& lights, const ShadingPoint& at,
                                   std::uint64_t seed) {
    constexpr std::size_t kDraws = 400000;
    ChiSquareResult r;
    r.alpha = sidakCorrectedAlpha(testing::kSignificance, kChiSquareTests);
    r.observed.assign(lights.size(), 0.0);
    r.expected.assign(lights.size(), 0.0);
    Pcg32 rng(seed);
    for (std::size_t k = 0; k < kDraws; ++k)
        if (const auto c = lights.choose(at.p, at.n, rng.nextFloat())) {
            r.observed[c->index] += 1.0;
            ++r.validSamples;
        }
    for (std::size_t i = 0; i < lights.size(); ++i)
        r.expected[i] = double(lights.probability(i, at.p, at.n)) * double(kDraws);
    if (pearsonStatistic(kDraws, r))
        r.message = "chi2 = " + std::to_string(r.statistic) + ", " +
                    std::to_string(r.degreesOfFreedom) + " dof, p = " + std::to_string(r.pValue);
    return r;
}

TEST(LightBvh, SelectionFrequenciesFollowTheProbabilities) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind),
                    many = manyLights();
    const Geometry mixedGeometry(mixed), manyGeometry(many);
    const LightSet mixedLights(mixed, mixedGeometry, LightSelection::Bvh);
    const LightSet manyLightSet(many, manyGeometry, LightSelection::Bvh);
    ASSERT_EQ(mixedLights.size(), 9u);
    ASSERT_EQ(manyLightSet.size(), 1056u);
    std::uint64_t seed = 1;
    for (const ShadingPoint& at : kMixedPoints)
        EXPECT_TRUE(testing::passes(selectionChiSquare(mixedLights, at, seed++)))
            << "mixed lights at " << at.p.x << " " << at.p.y << " " << at.p.z;
    for (const ShadingPoint& at : kManyLightPoints)
        EXPECT_TRUE(testing::passes(selectionChiSquare(manyLightSet, at, seed++)))
            << "many lights at " << at.p.x << " " << at.p.y << " " << at.p.z;
}

/// Random shading points in and around the scene's bounds, half of them with a normal.
std::vector<ShadingPoint> randomPoints(const Geometry& g, int count, std::uint64_t seed) {
    Pcg32 rng(seed);
    std::vector<ShadingPoint> points;
    for (int k = 0; k < count; ++k) {
        const Vec3f u(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        const Vec3f p = g.boundsCenter() + 1.2f * g.boundsRadius() * (2.0f * u - 1.0f);
        Vec3f n(0.0f);
        if (k % 2 == 0)
            n = safeNormalize(Vec3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) - 0.5f);
        points.push_back({p, n});
    }
    return points;
}

// Both scenes have point lights, which reach every point: the sum is 1 everywhere.
void expectANormalisedDistribution(const LightSet& lights, const Geometry& g, const char* what) {
    for (const ShadingPoint& at : randomPoints(g, 200, 3)) {
        double sum = 0;
        for (std::size_t i = 0; i < lights.size(); ++i)
            sum += lights.probability(i, at.p, at.n);
        EXPECT_NEAR(sum, 1.0, 1e-4) << what << " at " << at.p.x << " " << at.p.y << " " << at.p.z;
    }
}

TEST(LightBvh, ProbabilitiesSumToOne) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind),
                    many = manyLights();
    const Geometry mixedGeometry(mixed), manyGeometry(many);
    for (LightSelection s : {LightSelection::Bvh, LightSelection::Power, LightSelection::Uniform}) {
        expectANormalisedDistribution(LightSet(mixed, mixedGeometry, s), mixedGeometry,
                                      "mixed lights");
        expectANormalisedDistribution(LightSet(many, manyGeometry, s), manyGeometry, "many lights");
    }
}

TEST(LightBvh, ProbabilityIsExactlyWhatChooseReturns) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind),
                    many = manyLights();
    const Geometry mixedGeometry(mixed), manyGeometry(many);
    const LightSet mixedLights(mixed, mixedGeometry, LightSelection::Bvh);
    const LightSet manyLightSet(many, manyGeometry, LightSelection::Bvh);
    Pcg32 rng(5);
    for (const auto& [lights, geometry] :
         {std::pair{&mixedLights, &mixedGeometry}, std::pair{&manyLightSet, &manyGeometry}}) {
        int chosen = 0;
        for (const ShadingPoint& at : randomPoints(*geometry, 200, 4))
            for (int k = 0; k < 50; ++k) {
                const auto c = lights->choose(at.p, at.n, rng.nextFloat());
                if (!c) continue;
                ++chosen;
                ASSERT_GT(c->probability, 0.0f);
                ASSERT_EQ(c->probability, lights->probability(c->index, at.p, at.n));
            }
        EXPECT_GT(chosen, 7500);
    }
}

// Lights at infinity that next-event estimation samples take a fixed share n / (n + 1)
// whatever the point, split in proportion to their power distribution (which BDPT's MIS
// weights rely on). In the mixed scene the environment is constant, so the directional light
// is the one such light (1/2); with an image environment beside a constant one both
// environments are sampled (2/3) with the same ratio to their particle probabilities.
TEST(LightBvh, LightsAtInfinityTakeAFixedShare) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind);
    const Geometry geometry(mixed);
    const LightSet lights(mixed, geometry, LightSelection::Bvh);
    ASSERT_EQ(lights.infiniteLights().size(), 2u);
    for (const ShadingPoint& at : randomPoints(geometry, 50, 6)) {
        double share = 0;
        for (std::size_t i : lights.infiniteLights())
            share += lights.probability(i, at.p, at.n);
        EXPECT_NEAR(share, 0.5, 1e-6);
    }

    const fs::path dir =
        fs::temp_directory_path() / ("lamina-light-bvh-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path sky = dir / "sky.exr";
    const auto pixels = testing::skyTestImage(16, 8);
    std::vector<float> data;
    for (const Rgb<float>& px : pixels)
        for (int c = 0; c < 3; ++c)
            data.push_back(px[c]);
    writeFloatExr(sky, 16, 8, {"R", "G", "B"}, data);
    const SceneDesc twoSkies = testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "rectangle", "material": "m", "emission": {"radiance": 2}}],
      "lights": [{"type": "environment", "radiance": 0.3},
                 {"type": "environment", "file": ")" + sky.string() +
                                                      R"("}]
    })");
    const Geometry skiesGeometry(twoSkies);
    const LightSet skies(twoSkies, skiesGeometry, LightSelection::Bvh);
    fs::remove_all(dir);
    ASSERT_EQ(skies.infiniteLights().size(), 2u);
    for (const ShadingPoint& at : randomPoints(skiesGeometry, 50, 7)) {
        const std::size_t a = skies.infiniteLights()[0], b = skies.infiniteLights()[1];
        EXPECT_NEAR(skies.probability(a, at.p, at.n) + skies.probability(b, at.p, at.n), 2.0 / 3.0,
                    1e-6);
        EXPECT_NEAR(skies.probability(a, at.p, at.n) / skies.emitterProbability(a),
                    skies.probability(b, at.p, at.n) / skies.emitterProbability(b), 1e-5);
    }
}

// When every environment is constant, next-event estimation leaves them to BSDF sampling
// under every selection: probability 0 everywhere, never chosen, the other lights' share
// renormalised to 1; a scene lit by a constant environment alone has nothing to choose.
TEST(NextEventLights, ConstantEnvironmentsAreLeftToBsdfSampling) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind);
    const Geometry geometry(mixed);
    const SceneDesc skyOnly = testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "rectangle", "material": "m"}],
      "lights": [{"type": "environment", "radiance": 0.3}]
    })");
    const Geometry skyGeometry(skyOnly);
    Pcg32 rng(11);
    for (LightSelection s : {LightSelection::Bvh, LightSelection::Power, LightSelection::Uniform}) {
        const LightSet lights(mixed, geometry, s);
        const std::size_t sky = lights.infiniteLights()[1];
        ASSERT_TRUE(lights.light(sky).isInfinite() && !lights.light(sky).isDelta());
        EXPECT_FALSE(lights.nextEventSamples(sky));
        for (std::size_t i = 0; i < lights.size(); ++i)
            EXPECT_EQ(lights.nextEventSamples(i), i != sky) << "light " << i;
        for (const ShadingPoint& at : randomPoints(geometry, 50, 8)) {
            EXPECT_EQ(lights.probability(sky, at.p, at.n), 0.0f);
            for (int k = 0; k < 200; ++k) {
                const auto c = lights.choose(at.p, at.n, rng.nextFloat());
                ASSERT_TRUE(c);
                EXPECT_NE(c->index, sky);
            }
        }
        // The extreme random numbers too (the cdf's last entries).
        for (float u : {0.0f, kOneMinusEpsilon<float>}) {
            const auto c = lights.choose(Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), u);
            ASSERT_TRUE(c);
            EXPECT_NE(c->index, sky);
        }
        const LightSet alone(skyOnly, skyGeometry, s);
        ASSERT_EQ(alone.size(), 1u);
        EXPECT_FALSE(alone.choose(Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), 0.5f));
        EXPECT_EQ(alone.probability(0, Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f)), 0.0f);
    }
}

// A light that cannot send light to the point is never chosen: the spot light's cone points
// down from (0, 1, 0), so a point above it gets none; the one-sided rectangle at y = 2 faces
// +z (its winding), so a point behind it gets none.
TEST(LightBvh, LightsThatCannotReachThePointAreNeverChosen) {
    const SceneDesc mixed = testing::sceneFromText(testing::kOneEmitterOfEveryKind);
    const Geometry geometry(mixed);
    const LightSet lights(mixed, geometry, LightSelection::Bvh);
    std::size_t spot = lights.size(), rectangle = lights.size();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const auto b = lights.light(i).bounds();
        if (!b) continue;
        if (b->cosThetaO > -1.0f && b->cosThetaO < 1.0f) spot = i;
        if (b->cosThetaO == 1.0f && b->lower.y > 1.5f) rectangle = i;
    }
    ASSERT_LT(spot, lights.size());
    ASSERT_LT(rectangle, lights.size());
    EXPECT_EQ(lights.probability(spot, Vec3f(0.0f, 3.0f, 0.0f), Vec3f(0.0f)), 0.0f);
    EXPECT_GT(lights.probability(spot, Vec3f(0.0f, -1.0f, 0.0f), Vec3f(0.0f)), 0.0f);
    const Vec3f n = lights.light(rectangle).bounds()->axis;
    const Vec3f centre = lights.light(rectangle).bounds()->center();
    EXPECT_EQ(lights.probability(rectangle, centre - 2.0f * n, Vec3f(0.0f)), 0.0f);
    EXPECT_GT(lights.probability(rectangle, centre + 2.0f * n, Vec3f(0.0f)), 0.0f);
}

}  // namespace
}  // namespace lamina::render
