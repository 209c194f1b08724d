// Where light tracing and BDPT start particles in an emitting medium (medium_emitters.h,
// docs/media.md "Emitting media in light tracing and BDPT"): the sampled points against the
// density the MIS weights evaluate, by Pearson's chi-square test (fixed seeds, family-wise
// significance 0.01 over the two chi-square tests of this file, Sidak-corrected); the density
// integrates to 1 and equals the one a sample returns; the lights and the media share the
// particles, and a scene without emitting media keeps the light set's probabilities bit for bit.
// Broken once on purpose each: choosing a grid's cells uniformly instead of by their maxima
// fails the grid test; a homogeneous box without the margin taken into the density fails the
// homogeneous test.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/chi_square_test.h"
#include "lamina/core/pcg32.h"
#include "lamina/integrators/medium_emitters.h"
#include "lamina/render/camera.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

constexpr int kChiSquareTests = 2;
constexpr double kAlpha = 0.01;

/// What MediumEmitters is built from, kept alive together.
struct Built {
    explicit Built(const std::string& json)
        : scene(testing::sceneFromText(json)),
          geometry(scene),
          lights(scene, geometry, LightSelection::Power),
          camera(scene.camera, 8, 8),
          emitters(SceneContext{scene, geometry, lights, camera}, true) {}
    SceneDesc scene;
    Geometry geometry;
    LightSet lights;
    Camera camera;
    MediumEmitters emitters;
};

/// A puff of 32 x 8 x 8 densities (a blob, 0 in its first quarter along x), so that its 16 x 8
/// x 8 majorant cells have different maxima, stretched, rotated and moved by its transform,
/// beside a lamp.
std::string gridScene() {
    std::string values;
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 32; ++x) {
                const double dx = (x - 20) / 6.0, dy = (y - 3) / 2.5, dz = (z - 4) / 3.0;
                const double v = x < 8 ? 0.0 : 3 * std::exp(-(dx * dx + dy * dy + dz * dz));
                values += (values.empty() ? "" : ", ") + std::to_string(v);
            }
    return R"({
  "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
  "media": {"puff": {"type": "grid", "sigma_a": [0.5, 1, 2], "Le": 1, "edges": "zero",
                     "bounds": {"min": [-1, -0.5, -0.5], "max": [1, 0.5, 0.5]},
                     "density": {"size": [32, 8, 8], "values": [)" +
           values + R"(]},
                     "transform": [{"scale": [1.5, 0.8, 1.2]},
                                   {"rotate": {"axis": [1, 2, 0.5], "angle": 35}},
                                   {"translate": [0.3, -0.2, 0.4]}]}},
  "materials": {"m": {"type": "lambert"}},
  "shapes": [{"type": "sphere", "radius": 3, "material": "interface", "interior": "puff"},
             {"type": "rectangle", "material": "m", "emission": {"radiance": 2},
              "transform": [{"translate": [0, 0, 4]}]}]})";
}

TEST(MediumEmitters, GridPointsFollowTheMajorantCellsChiSquare) {
    const Built b(gridScene());
    ASSERT_FALSE(b.emitters.empty());
    const GridDensity& grid = *b.scene.media[0].grid;
    const MajorantGrid& maj = grid.majorants;
    const int nx = maj.nx, ny = maj.ny, nz = maj.nz;
    ASSERT_EQ(nx * ny * nz, 16 * 8 * 8);
    double total = 0, largest = 0;
    for (float m : maj.maxima) {
        total += m;
        largest = std::max(largest, double(m));
    }
    // The cells' maxima differ (else any choice of cells would pass): some are 0.
    ASSERT_EQ(maj.maxima.front(), 0.0f);
    ASSERT_GT(largest, 2.0);
    // The medium's space is the scene's scaled by 1.5 x 0.8 x 1.2 (and rotated, moved).
    const double cellVolume = 2.0 * 1.0 * 1.0 / (nx * ny * nz) * 1.5 * 0.8 * 1.2;
    // Each majorant cell in 2 x 2 x 2 bins, in the medium's space.
    constexpr int kSub = 2;
    const int bx = nx * kSub, by = ny * kSub, bz = nz * kSub;
    ChiSquareResult result;
    result.observed.assign(std::size_t(bx * by * bz), 0.0);
    result.expected.assign(result.observed.size(), 0.0);
    constexpr std::size_t kSamples = 400000;
    Pcg32 rng(29);
    // The density a sample returns, and the one the weights evaluate at its point, against
    // its cell's own: a point that rounding carries across a cell's face (its bin is then the
    // neighbour's) may differ, a few in a million.
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const Vec3f u(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        const auto v = b.emitters.samplePoint(0, u);
        ASSERT_TRUE(v);
        const Vec3f local = grid.local(grid.pointToMedium(v->p));
        const int x = std::clamp(int(local.x * float(bx)), 0, bx - 1),
                  y = std::clamp(int(local.y * float(by)), 0, by - 1),
                  z = std::clamp(int(local.z * float(bz)), 0, bz - 1);
        result.observed[std::size_t((z * by + y) * bx + x)] += 1;
        // The density the sample returns, the one the weights evaluate, and the cell's own.
        const int c = (z / kSub * ny + y / kSub) * nx + x / kSub;
        const double own = maj.maxima[std::size_t(c)] / total / cellVolume;
        if (std::abs(v->pdf / own - 1) > 1e-3 ||
            std::abs(b.emitters.pointDensity(0, v->p) / own - 1) > 1e-3)
            ++mismatches;
    }
    EXPECT_LE(mismatches, kSamples / 100000);
    for (int z = 0; z < bz; ++z)
        for (int y = 0; y < by; ++y)
            for (int x = 0; x < bx; ++x) {
                const int c = (z / kSub * ny + y / kSub) * nx + x / kSub;
                result.expected[std::size_t((z * by + y) * bx + x)] =
                    double(kSamples) * maj.maxima[std::size_t(c)] / total / (kSub * kSub * kSub);
            }
    result.alpha = sidakCorrectedAlpha(kAlpha, kChiSquareTests);
    ASSERT_TRUE(pearsonStatistic(kSamples, result)) << result.message;
    EXPECT_TRUE(result.passed) << "chi-square " << result.statistic << " on "
                               << result.degreesOfFreedom << " dof, p = " << result.pValue;

    // The density integrates to 1 over the scene: uniform points in a box around the
    // transformed grid box (its corners are within 3 of the origin).
    Pcg32 mc(31);
    constexpr int kPoints = 400000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < kPoints; ++i) {
        const Vec3f p(6 * mc.nextFloat() - 3, 6 * mc.nextFloat() - 3, 6 * mc.nextFloat() - 3);
        const double f = 216.0 * b.emitters.pointDensity(0, p);
        sum += f;
        sum2 += f * f;
    }
    const double mean = sum / kPoints, se = std::sqrt((sum2 / kPoints - mean * mean) / kPoints);
    EXPECT_LT(std::abs(mean - 1), 3.29 * se) << mean << " +- " << se;
}

/// A glowing sphere (centre (1, 0.5, -0.3), radius 0.7) beside a lamp.
const char* kSphereScene = R"({
  "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
  "media": {"glow": {"type": "homogeneous", "sigma_a": 0.5, "Le": [1, 2, 3]}},
  "materials": {"m": {"type": "lambert"}},
  "shapes": [{"type": "sphere", "center": [1, 0.5, -0.3], "radius": 0.7, "material": "interface",
              "interior": "glow"},
             {"type": "rectangle", "material": "m", "emission": {"radiance": 2},
              "transform": [{"translate": [0, 0, 4]}]}]})";

TEST(MediumEmitters, HomogeneousPointsAreUniformInTheBoundingShapesBoxChiSquare) {
    const Built b(kSphereScene);
    ASSERT_FALSE(b.emitters.empty());
    const Vec3f centre(1, 0.5f, -0.3f);
    // The sphere's box, with the margin of 1e-4 of its side and 1e-6 on each side.
    const double side = 1.4 * (1 + 2e-4) + 2e-6;
    constexpr int kBins = 5;
    ChiSquareResult result;
    result.observed.assign(kBins * kBins * kBins, 0.0);
    result.expected.assign(result.observed.size(), 0.0);
    constexpr std::size_t kSamples = 200000;
    Pcg32 rng(37);
    std::size_t inside = 0;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const auto v =
            b.emitters.samplePoint(0, Vec3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()));
        ASSERT_TRUE(v);
        EXPECT_NEAR(v->pdf * side * side * side, 1.0, 1e-4);
        EXPECT_EQ(b.emitters.pointDensity(0, v->p), v->pdf);
        const Vec3f f = (v->p - centre) / float(side) + 0.5f;
        int bin[3];
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(f[k], -1e-5f);
            ASSERT_LE(f[k], 1.0f + 1e-5f);
            bin[k] = std::clamp(int(f[k] * kBins), 0, kBins - 1);
        }
        result.observed[std::size_t((bin[2] * kBins + bin[1]) * kBins + bin[0])] += 1;
        if (glm::length(v->p - centre) < 0.7f) ++inside;
    }
    for (double& e : result.expected)
        e = double(kSamples) / (kBins * kBins * kBins);
    result.alpha = sidakCorrectedAlpha(kAlpha, kChiSquareTests);
    ASSERT_TRUE(pearsonStatistic(kSamples, result)) << result.message;
    EXPECT_TRUE(result.passed) << "chi-square " << result.statistic << ", p = " << result.pValue;
    // The sphere fills pi / 6 of its box: the share of points that carry its emission.
    const double share = double(inside) / kSamples, expected = kPi<double> / 6;
    EXPECT_LT(std::abs(share - expected), 3.29 * std::sqrt(expected * (1 - expected) / kSamples));
    EXPECT_EQ(b.emitters.pointDensity(0, centre + Vec3f(0.8f, 0, 0)), 0.0f);
    EXPECT_EQ(b.emitters.pointDensity(1, centre), 0.0f);  // no such medium
}

TEST(MediumEmitters, LightsAndMediaShareTheParticles) {
    const Built b(kSphereScene);
    ASSERT_EQ(b.lights.size(), 1u);
    const float light = b.emitters.lightProbability(0), medium = b.emitters.mediumProbability(0);
    EXPECT_GT(light, 0.0f);
    EXPECT_GT(medium, 0.0f);
    EXPECT_NEAR(light + medium, 1.0f, 1e-6f);
    // choose() returns each with its probability, and the light as the light set would.
    int media = 0;
    constexpr int kDraws = 100000;
    for (int i = 0; i < kDraws; ++i) {
        const auto c = b.emitters.choose((float(i) + 0.5f) / kDraws);
        if (c.medium == 0) {
            ++media;
            EXPECT_EQ(c.probability, medium);
        } else {
            EXPECT_EQ(c.light, 0);
            EXPECT_EQ(c.probability, light);
        }
    }
    EXPECT_NEAR(double(media) / kDraws, medium, 1e-4);
    // Without an emitting medium the light set's own probabilities, bit for bit.
    std::string dark = kSphereScene;
    dark.replace(dark.find(R"(, "Le": [1, 2, 3])"), std::string(R"(, "Le": [1, 2, 3])").size(), "");
    const Built d(dark);
    EXPECT_TRUE(d.emitters.empty());
    EXPECT_EQ(d.emitters.lightProbability(0), d.lights.emitterProbability(0));
    EXPECT_EQ(d.emitters.mediumProbability(0), 0.0f);
}

}  // namespace
}  // namespace lamina::render
