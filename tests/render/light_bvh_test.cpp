// The light BVH's distribution (light_bvh.h, LightSet's `bvh` selection) at shading points:
// choose() must draw each light with the probability probability() reports, exactly the
// value it returns with the light, and the probabilities of all lights must sum to 1. Scenes: one
// light of every kind (with a directional light, which takes the fixed share, and a constant
// environment, which next-event estimation leaves to BSDF sampling) and scenes/many-lights.json
// (1056 lights). Chi-square: 400 000 draws per point, cells with an
// expected count below 5 pooled, 8 points at a family-wise significance of 1% (Sidak).
// The tree keeps its nodes' children's bounds prepared for the importance and evaluates the
// two together (ImportancePair) and skips work whose result is unused: the importances and
// the probabilities must be the same floats as by the definition, at random bounds and
// points, in the two-light tree of the Cornell box and in a one-light tree.
#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/lights/lights.h"
#include "lamina/output/image_output.h"
#include "render_helpers.h"
#include "source_files.h"

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
    return loadScene(testing::sourceFile("scenes/many-lights.json"));
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

// Conty Estevez and Kulla 2018, eq. 3, with pbrt-v4's receiver term, everything derived from
// the bounds at the query, in the order of operations LightBounds::importance had before the
// tree's nodes kept ImportanceBounds (the prepared form must give the same float, so that
// images and every probability stay as they were).
float importanceByTheDefinition(const LightBounds& b, const Vec3f& p, const Vec3f& n) {
    const auto sinOf = [](float c) { return safeSqrt(1.0f - c * c); };
    // cos and sin of max(0, a - b) from the angles' cosines and sines.
    const auto cosMinus = [](float cosA, float sinA, float cosB, float sinB) {
        return cosA >= cosB ? 1.0f : cosA * cosB + sinA * sinB;
    };
    const auto sinMinus = [](float cosA, float sinA, float cosB, float sinB) {
        return cosA >= cosB ? 0.0f : sinA * cosB - cosA * sinB;
    };
    const Vec3f toP = p - 0.5f * (b.lower + b.upper);
    const float d2 = glm::dot(toP, toP);
    const float r2 = 0.25f * lengthSquared(b.upper - b.lower);
    const float cosU = d2 > r2 ? safeSqrt(1.0f - r2 / d2) : -1.0f;
    const float sinU = d2 > r2 ? std::sqrt(r2 / d2) : 0.0f;
    const Vec3f w = d2 > 0.0f ? toP / std::sqrt(d2) : Vec3f(0.0f);
    const float cosTheta = b.twoSided ? std::abs(glm::dot(b.axis, w)) : glm::dot(b.axis, w);
    const float sinTheta = sinOf(cosTheta), sinO = sinOf(b.cosThetaO);
    const float cosX = cosMinus(cosTheta, sinTheta, b.cosThetaO, sinO);
    const float sinX = sinMinus(cosTheta, sinTheta, b.cosThetaO, sinO);
    const float cosThetaP = cosMinus(cosX, sinX, cosU, sinU);
    if (cosThetaP <= b.cosThetaE) return 0.0f;
    float value =
        b.intensity * cosThetaP / std::max({d2, 0.25f * r2, std::numeric_limits<float>::min()});
    if (n != Vec3f(0.0f)) {
        const float cosI = std::abs(glm::dot(n, w));
        value *= cosMinus(cosI, sinOf(cosI), cosU, sinU);
    }
    return value > 0.0f ? std::min(value, std::numeric_limits<float>::max()) : 0.0f;
}

/// Random bounds: boxes from points to 3 units wide (flat ones too), cones of normals from a
/// single direction to the sphere, surfaces and spot-light bands, one- and two-sided.
LightBounds randomBounds(Pcg32& rng) {
    const auto in = [&rng](float lo, float hi) { return lo + (hi - lo) * rng.nextFloat(); };
    LightBounds b;
    b.lower = Vec3f(in(-2.0f, 2.0f), in(-2.0f, 2.0f), in(-2.0f, 2.0f));
    Vec3f extent(in(0.0f, 3.0f), in(0.0f, 3.0f), in(0.0f, 3.0f));
    const std::uint32_t shape = rng.nextUint32() % 4;
    if (shape == 0) extent = Vec3f(0.0f);  // a point light
    if (shape == 1) extent.y = 0.0f;       // a flat light
    b.upper = b.lower + extent;
    b.axis = safeNormalize(Vec3f(in(-1.0f, 1.0f), in(-1.0f, 1.0f), in(-1.0f, 1.0f)));
    const std::uint32_t cone = rng.nextUint32() % 3;
    b.cosThetaO = cone == 0 ? 1.0f : cone == 1 ? -1.0f : in(-1.0f, 1.0f);
    b.cosThetaE = rng.nextUint32() % 2 == 0 ? 0.0f : in(0.0f, 1.0f);
    b.intensity = rng.nextUint32() % 8 == 0 ? 0.0f : in(0.0f, 10.0f);
    b.twoSided = rng.nextUint32() % 2 == 0;
    return b;
}

// The prepared bounds (ImportanceBounds) and the tree's two-at-a-time evaluation
// (ImportancePair, SSE lanes) against the definition, bit for bit.
TEST(LightBvh, PreparedBoundsGiveTheImportanceOfTheDefinition) {
    Pcg32 rng(21);
    int positive = 0;
    LightBounds previous = randomBounds(rng);
    for (int k = 0; k < 200000; ++k) {
        const LightBounds b = randomBounds(rng);
        // Points outside and inside the box, and its centre (distance 0).
        const std::uint32_t where = rng.nextUint32() % 8;
        Vec3f p = b.center();
        if (where > 0) {
            const Vec3f u(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
            p = where < 3 ? b.lower + u * (b.upper - b.lower) : 8.0f * u - 4.0f;
        }
        Vec3f n(0.0f);
        if (rng.nextUint32() % 3 != 0)
            n = safeNormalize(Vec3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) - 0.5f);
        const float expected = importanceByTheDefinition(b, p, n);
        const float prepared = ImportanceBounds(b).importance(p, n);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(prepared), std::bit_cast<std::uint32_t>(expected))
            << "sample " << k << ": " << prepared << " against " << expected;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(b.importance(p, n)),
                  std::bit_cast<std::uint32_t>(expected));
        // The pair in both orders: each lane is its cluster's importance.
        const float other = importanceByTheDefinition(previous, p, n);
        const auto ab =
            ImportancePair(ImportanceBounds(b), ImportanceBounds(previous)).importances(p, n);
        const auto ba =
            ImportancePair(ImportanceBounds(previous), ImportanceBounds(b)).importances(p, n);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(ab[0]), std::bit_cast<std::uint32_t>(expected))
            << "sample " << k << ": " << ab[0] << " against " << expected;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(ab[1]), std::bit_cast<std::uint32_t>(other));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(ba[0]), std::bit_cast<std::uint32_t>(other));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(ba[1]), std::bit_cast<std::uint32_t>(expected));
        if (expected > 0.0f) ++positive;
        previous = b;
    }
    EXPECT_GT(positive, 50000);  // the comparisons are not all of zeros
}

// The Cornell box's lamp as two triangle lights: a tree of one node and two leaves, no lights at
// infinity, whose choice is one comparison of u with the left share l / (l + r) (in double,
// as LightBvh computes it) and no rescaling of u. At random points its probabilities and
// choices must be exactly those of the definition, u just below and at the share included.
TEST(LightBvh, TwoLightTreeChoosesByTheShareOfTheDefinition) {
    SceneDesc box = loadScene(testing::sourceFile("scenes/cornell-box.json"));
    // The lamp's two triangles with vertices of their own, so that they are two lights (two
    // triangles on four vertices that make a rectangle are one, RectangleLight::isRectangle).
    for (ShapeDesc& shape : box.shapes)
        if (auto* m = std::get_if<MeshDesc>(&shape); m && m->name == "light") {
            const auto p = m->positions;
            m->positions = {p[0], p[1], p[2], p[2], p[3], p[0]};
            m->triangles = {{0, 1, 2}, {3, 4, 5}};
        }
    const Geometry geometry(box);
    const LightSet lights(box, geometry, LightSelection::Bvh);
    ASSERT_EQ(lights.size(), 2u);
    ASSERT_TRUE(lights.infiniteLights().empty());
    const LightBounds b0 = *lights.light(0).bounds(), b1 = *lights.light(1).bounds();
    // Neither is below the intensity floor LightSet gives zero-luminance lights.
    ASSERT_GT(std::min(b0.intensity, b1.intensity), 1e-6f * std::max(b0.intensity, b1.intensity));
    // The left leaf is the one u = 0 reaches at a point both lights light.
    const Vec3f below = 0.5f * (b0.center() + b1.center()) - Vec3f(0.0f, 100.0f, 0.0f);
    const std::size_t left = lights.choose(below, Vec3f(0.0f, 1.0f, 0.0f), 0.0f)->index;
    const std::size_t right = 1 - left;
    const LightBounds& bLeft = left == 0 ? b0 : b1;
    const LightBounds& bRight = left == 0 ? b1 : b0;
    Pcg32 rng(22);
    int split = 0;
    for (const ShadingPoint& at : randomPoints(geometry, 5000, 23)) {
        const double l = importanceByTheDefinition(bLeft, at.p, at.n);
        const double r = importanceByTheDefinition(bRight, at.p, at.n);
        const float pLeft = l + r > 0.0 ? float(l / (l + r)) : 0.5f;
        ASSERT_EQ(lights.probability(left, at.p, at.n), pLeft);
        ASSERT_EQ(lights.probability(right, at.p, at.n), 1.0f - pLeft);
        if (pLeft > 0.0f && pLeft < 1.0f) ++split;
        for (const float u : {rng.nextFloat(), pLeft, std::nextafter(pLeft, 0.0f)}) {
            if (!(u < 1.0f)) continue;
            const auto c = lights.choose(at.p, at.n, u);
            ASSERT_TRUE(c);
            const bool toLeft = u < pLeft;
            EXPECT_EQ(c->index, toLeft ? left : right) << "u " << u << ", share " << pLeft;
            EXPECT_EQ(c->probability, toLeft ? pLeft : 1.0f - pLeft);
        }
    }
    EXPECT_GT(split, 2000);  // most points see both triangles
}

// A tree of one leaf: that light whatever u, with probability exactly 1.
TEST(LightBvh, OneLightTreeAlwaysChoosesIt) {
    const SceneDesc one = testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "mesh", "material": "m", "emission": {"radiance": 3},
                  "positions": [[0, 0, 0], [1, 0, 0], [0, 0, 1]], "faces": [[0, 2, 1]]}]
    })");
    const Geometry geometry(one);
    const LightSet lights(one, geometry, LightSelection::Bvh);
    ASSERT_EQ(lights.size(), 1u);
    for (const ShadingPoint& at : randomPoints(geometry, 200, 24)) {
        EXPECT_EQ(lights.probability(0, at.p, at.n), 1.0f);
        for (const float u : {0.0f, 0.5f, kOneMinusEpsilon<float>}) {
            const auto c = lights.choose(at.p, at.n, u);
            ASSERT_TRUE(c);
            EXPECT_EQ(c->index, 0u);
            EXPECT_EQ(c->probability, 1.0f);
        }
    }
}

// choose() reads no number exactly when it has one light to return (the integrators then skip
// the sampler's dimension), and returns none exactly when nextEventChooses() says so (a
// constant sky alone): under every selection, on scenes with one light (a triangle; a
// rectangle beside a constant environment, which next-event estimation leaves to BSDF
// sampling; a directional light alone) every u gives the same choice, bit for bit, at random
// points; on scenes with several (two triangles, one emitter of every kind, the many-light
// scene) some point has two numbers that choose different lights. chooseEmitter() reads none
// only with one light in all.
TEST(LightSet, ChoiceReadsNoNumberExactlyWhenThereIsOneLightToChoose) {
    const std::string triangle = R"({"type": "mesh", "material": "m", "emission": {"radiance": 3},
        "positions": [[0, 0, 0], [1, 0, 0], [0, 0, 1]], "faces": [[0, 2, 1]]})";
    auto scene = [](const std::string& shapes, const std::string& lights) {
        return testing::sceneFromText(R"({"materials": {"m": {"type": "lambert"}},
            "shapes": [{"type": "sphere", "center": [0, -2, 0], "radius": 1, "material": "m"})" +
                                      shapes + R"(], "lights": [)" + lights + "]}");
    };
    struct Case {
        const char* name;
        SceneDesc scene;
        bool severalChoices, severalEmitters;
        bool chooses = true;
    };
    // The triangle and its neighbour across the edge (1, 2), both facing +y.
    SceneDesc twoTriangles = scene(", " + triangle, "");
    // The second triangle's far corner off the square, so the two are not one rectangle light.
    // (The meshes come first among the shapes: the triangle is the first shape.)
    MeshDesc& pair = std::get<MeshDesc>(twoTriangles.shapes[0]);
    pair.positions.push_back({2, 0, 1});
    pair.triangles.push_back({1, 2, 3});
    const Case cases[] = {
        {"one triangle", scene(", " + triangle, ""), false, false},
        {"rectangle and constant sky",
         scene(R"(, {"type": "rectangle", "material": "m", "emission": {"radiance": 1}})",
               R"({"type": "environment", "radiance": 0.3})"),
         false, true},
        {"directional light",
         scene("", R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 1})"), false,
         false},
        {"two triangles", twoTriangles, true, true},
        {"one emitter of every kind", testing::sceneFromText(testing::kOneEmitterOfEveryKind), true,
         true},
        {"many lights", manyLights(), true, true},
        {"constant sky alone", scene("", R"({"type": "environment", "radiance": 0.3})"), false,
         false, false},
    };
    const float us[] = {0.0f, 0.1f, 0.3f, 0.5f, 0.7f, 0.9f, kOneMinusEpsilon<float>};
    for (const Case& c : cases)
        for (LightSelection s :
             {LightSelection::Bvh, LightSelection::Power, LightSelection::Uniform}) {
            const Geometry geometry(c.scene);
            const LightSet lights(c.scene, geometry, s);
            EXPECT_EQ(lights.choiceReadsNumber(), c.severalChoices) << c.name;
            EXPECT_EQ(lights.emitterChoiceReadsNumber(), c.severalEmitters) << c.name;
            EXPECT_EQ(lights.nextEventChooses(), c.chooses) << c.name;
            bool differs = false;
            for (const ShadingPoint& at : randomPoints(geometry, 100, 31)) {
                if (!c.chooses) {
                    for (const float u : us)
                        EXPECT_FALSE(lights.choose(at.p, at.n, u)) << c.name;
                    continue;
                }
                const auto first = lights.choose(at.p, at.n, us[0]);
                ASSERT_TRUE(first) << c.name;
                for (const float u : us) {
                    const auto other = lights.choose(at.p, at.n, u);
                    ASSERT_TRUE(other) << c.name;
                    differs = differs || other->index != first->index ||
                              other->probability != first->probability;
                }
            }
            EXPECT_EQ(differs, c.severalChoices) << c.name << ", selection " << int(s);
        }
}

}  // namespace
}  // namespace lamina::render
