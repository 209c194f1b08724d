// Grid media (docs/media.md, "Grid media"), with known answers, fixed seeds and z-tests at
// two-sided significance 0.001 per channel and comparison:
// - delta and ratio tracking against Beer-Lambert through a grid of two densities (half the
//   box at d1, half at d2), with the spectral MIS over the channels of the integrators (an
//   estimate over the average of its densities per channel): the probability of passing and of
//   scattering, ratio tracking's transmittance, and the two combined by the balance heuristic
//   over strategies and channels as next-event estimation and scattering are;
// - path tracing through a slab of the same grid against exp(-sigma_t (d1 + d2) L / 2), and the
//   same seen by light tracing (ratio tracking of the camera connection), and the slab emitting
//   (Le_behind T + Le (1 - T): the emission at every tentative collision);
// - a grid of constant density renders the image of the homogeneous medium of the same
//   coefficients (path, RGB and spectral), with majorants 1.5 times too large so that null
//   collisions happen everywhere;
// - next-event estimation with ratio tracking against phase-function sampling alone through a
//   heterogeneous grid.
// Broken once on purpose each: majorants 20% too small (MajorantGrid::build's maxima times 0.8)
// fail both tracking tests (ratio tracking's red 17% too bright) and Beer-Lambert by path and
// light tracing (the constant grid's majorants, 1.5 times too large, stay conservative); a null
// collision that leaves the throughput and rU alone (the hero's own weight, 1, for every
// channel: the per-channel-biased shortcut) fails DeltaTrackingPassesAndScattersWithBeerLambert
// in every channel (passing: red 8% high, green and blue 44% low) and the RGB Beer-Lambert;
// ratio tracking's rL left at 1 (no MIS over the tracking's channels) fails
// RatioTrackingMatchesBeerLambert (red 38% low); delta tracking's rL without the null
// collisions' factor, or ratio tracking's passing without it, fails
// DeltaAndRatioTrackingCombineByTheBalanceHeuristic (green 8% high; every channel 8% to 55%
// low); the emission not scaled by the density fails EmissionOfAnAbsorbingSlab (blue 36%
// high). (The path integrator without the null collisions' rL changes the NEE test's image by
// 0.5%, below what it resolves: the tracking-level test is the one that sees it.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lamina/integrators/grid_tracking.h"
#include "media_render_helpers.h"

namespace lamina::render {
namespace {

using testing::ImageMean;
using testing::Rendered;
using testing::sceneFromText;
using testing::welch;

constexpr double kZ = 3.29;  // two-sided significance 0.001

/// Half the box at d1, half at d2 along x: values at the centres of four cells, so the density
/// is d1 on [0, 3/8], d2 on [5/8, 1] and linear between: along x its integral over the box is
/// (d1 + d2) / 2 times the box's length, as for a step in the middle.
GridDensity twoDensities(float d1, float d2, Vec3f boxMin, Vec3f boxMax) {
    GridDensity g;
    g.boxMin = boxMin;
    g.boxMax = boxMax;
    g.density.nx = 4;
    g.density.values = {d1, d1, d2, d2};
    g.majorants = MajorantGrid::build(g.density);
    return g;
}

struct Mean {
    double sum = 0, sum2 = 0;
    int n = 0;
    void add(double v) {
        sum += v;
        sum2 += v * v;
        ++n;
    }
    double mean() const { return sum / n; }
    double standardError() const {
        return std::sqrt(std::max(sum2 / n - sqr(mean()), 0.0) / (n - 1));
    }
};

void expectMean(const Mean& m, double expected, const std::string& what) {
    EXPECT_LT(std::abs(m.mean() - expected), kZ * m.standardError() + 1e-9)
        << what << ": " << m.mean() << " +- " << m.standardError() << ", expected " << expected;
}

// A chromatic medium along a ray crossing the two-density box from x = 0 to x = 2 (obliquely).
struct TrackingCase {
    GridDensity grid = twoDensities(0.3f, 1.7f, Vec3f(0.0f), Vec3f(2.0f, 1.0f, 1.0f));
    MediumCoefficients<Rgb<float>> m;
    Vec3f o{0.0f, 0.3f, 0.4f}, d = glm::normalize(Vec3f(1.0f, 0.2f, 0.1f));
    double length = 2.0 / double(glm::normalize(Vec3f(1.0f, 0.2f, 0.1f)).x);
    TrackingCase() {
        m.sigmaA = Rgb<float>(0.1f, 0.5f, 1.0f);
        m.sigmaS = Rgb<float>(0.4f, 1.0f, 3.0f);
        m.grid = &grid;
    }
    /// exp(-sigma_t (d1 + d2) / 2 length)
    double transmittance(int c) const {
        return std::exp(-double(m.sigmaT()[c]) * 0.5 * (0.3 + 1.7) * length);
    }
};

TEST(GridTracking, RatioTrackingMatchesBeerLambert) {
    const TrackingCase tc;
    std::mt19937_64 rng(1);
    Mean mis[3], own[3];
    for (int i = 0; i < 30000; ++i) {
        const int hero = int(rng() % 3);
        Transmittance<Rgb<float>> tr;
        ratioTrack(tc.m, tc.o - tc.d, tc.d, std::numeric_limits<float>::infinity(), hero, rng(),
                   tr);
        // The connections' estimator (MIS over the channels), and each hero's own channel.
        for (int c = 0; c < 3; ++c)
            mis[c].add(double(tr.T[c] / tr.rL.average()));
        own[hero].add(double(tr.T[hero]));
    }
    for (int c = 0; c < 3; ++c) {
        expectMean(mis[c], tc.transmittance(c), "spectral MIS, channel " + std::to_string(c));
        expectMean(own[c], tc.transmittance(c), "hero's own channel " + std::to_string(c));
    }
}

TEST(GridTracking, DeltaTrackingPassesAndScattersWithBeerLambert) {
    const TrackingCase tc;
    std::mt19937_64 rng(2);
    Mean passes[3], scatters[3];
    for (int i = 0; i < 30000; ++i) {
        const int hero = int(rng() % 3);
        Rgb<float> beta(1.0f), rU(1.0f), rL(1.0f);
        const FlightOutcome f =
            deltaTrack(tc.m, tc.o, tc.d, std::numeric_limits<float>::infinity(), hero, rng(), beta,
                       rU, &rL, static_cast<Rgb<float>*>(nullptr), TransportAblations{});
        // The path integrator's estimate of a flight: beta over the average density ratio.
        for (int c = 0; c < 3; ++c) {
            const double v = double(beta[c] / rU.average());
            passes[c].add(f.outcome == FlightOutcome::Outcome::Passes ? v : 0.0);
            scatters[c].add(f.outcome == FlightOutcome::Outcome::Scatters ? v : 0.0);
        }
    }
    for (int c = 0; c < 3; ++c) {
        const double T = tc.transmittance(c);
        expectMean(passes[c], T, "passing, channel " + std::to_string(c));
        // The integral of T(t) sigma_s(t) dt along the ray: the albedo times (1 - T).
        const double albedo = double(tc.m.sigmaS[c] / tc.m.sigmaT()[c]);
        expectMean(scatters[c], albedo * (1.0 - T), "scattering, channel " + std::to_string(c));
    }
}

// Next-event estimation and scattering combined on one segment, as the path integrator
// combines them (with the light's and the phase function's densities 1): delta tracking that
// passes, over the channels' average of its rU + rL, plus ratio tracking, over the average of
// its passing + rL, estimate T per channel together (the balance heuristic over the two
// strategies and the channels on the null-scattering paths). Checks that delta tracking's rL
// and ratio tracking's passing are the densities of the other strategy.
TEST(GridTracking, DeltaAndRatioTrackingCombineByTheBalanceHeuristic) {
    const TrackingCase tc;
    std::mt19937_64 rng(3);
    Mean both[3];
    for (int i = 0; i < 30000; ++i) {
        const int hero = int(rng() % 3);
        Rgb<float> beta(1.0f), rU(1.0f), rL(1.0f);
        const FlightOutcome f =
            deltaTrack(tc.m, tc.o, tc.d, std::numeric_limits<float>::infinity(), hero, rng(), beta,
                       rU, &rL, static_cast<Rgb<float>*>(nullptr), TransportAblations{});
        Transmittance<Rgb<float>> tr;
        ratioTrack(tc.m, tc.o, tc.d, std::numeric_limits<float>::infinity(), hero, rng(), tr);
        for (int c = 0; c < 3; ++c) {
            const double scattering = f.outcome == FlightOutcome::Outcome::Passes
                                          ? double(beta[c] / (rU + rL).average())
                                          : 0.0;
            both[c].add(scattering + double(tr.T[c] / (tr.passing + tr.rL).average()));
        }
    }
    for (int c = 0; c < 3; ++c)
        expectMean(both[c], tc.transmittance(c), "both strategies, channel " + std::to_string(c));
}

Rendered render(const SceneDesc& scene, RenderModeKind mode, int spp, std::uint64_t seed,
                IntegratorKind integrator = IntegratorKind::Path, bool nextEvent = true) {
    return testing::renderMeans(scene, mode, spp, seed, nextEvent, integrator);
}

/// The grid of medium `index` replaced by `grid` (the scene's media share their grids).
void replaceGrid(SceneDesc& scene, std::size_t index, GridDensity grid) {
    scene.media[index].grid = std::make_shared<const GridDensity>(std::move(grid));
}

/// Every majorant times `factor` (> 1: still conservative, more null collisions).
GridDensity scaledMajorants(GridDensity g, float factor) {
    for (float& v : g.majorants.maxima)
        v *= factor;
    return g;
}

class GridMediaRender : public ::testing::TestWithParam<RenderModeKind> {};

// A slab 1.5 thick between two interfaces, seen along its normal (z) by an orthographic camera
// in front of an emitter: d1 on the near half, d2 on the far half.
std::string gridSlab(const std::string& sigma, const std::string& more = "") {
    return R"({
      "camera": {"type": "orthographic", "position": [0, 0, -2], "look_at": [0, 0, 0]},
      "film": {"resolution": [8, 8]},
      "media": {"slab": {"type": "grid", "sigma_a": )" +
           sigma + more + R"(, "density": {"size": [1, 1, 4], "values": [0.4, 0.4, 1.6, 1.6]},
                         "bounds": {"min": [-3, -3, 0], "max": [3, 3, 1.5]}}},
      "materials": {"black": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "rectangle", "material": "interface", "exterior": "slab",
         "transform": [{"scale": 4}]},
        {"type": "rectangle", "material": "interface", "interior": "slab",
         "transform": [{"scale": 4}, {"translate": [0, 0, 1.5]}]},
        {"type": "rectangle", "material": "black", "emission": {"radiance": [2, 1, 0.5]},
         "transform": [{"scale": 6}, {"rotate": {"axis": [1, 0, 0], "angle": 180}},
                       {"translate": [0, 0, 3]}]}]})";
}

void expectBeerLambert(RenderModeKind mode, IntegratorKind integrator) {
    // RGB mode: a chromatic absorber; spectral mode a grey one (an upsampled chromatic
    // coefficient varies over each channel's wavelengths).
    const Rgb<double> sigma =
        mode == RenderModeKind::Rgb ? Rgb<double>(0.2, 0.7, 1.5) : Rgb<double>(0.9);
    const std::string s = "[" + std::to_string(sigma[0]) + ", " + std::to_string(sigma[1]) + ", " +
                          std::to_string(sigma[2]) + "]";
    // Light tracing's splats are noisier: 16 times the particles.
    const int spp = integrator == IntegratorKind::Light ? 4096 : 256;
    const Rendered withMedium = render(sceneFromText(gridSlab(s)), mode, spp, 3, integrator);
    const Rendered vacuum = render(sceneFromText(gridSlab("0")), mode, spp / 4, 4, integrator);
    for (int c = 0; c < 3; ++c) {
        const double T = std::exp(-sigma[c] * 0.5 * (0.4 + 1.6) * 1.5);
        const ImageMean &m = withMedium.channel[c], &v = vacuum.channel[c];
        const double se = std::hypot(m.standardError, T * v.standardError);
        EXPECT_LT(std::abs(m.mean - T * v.mean), kZ * se + 1e-6)
            << "channel " << c << ": " << m.mean << " +- " << m.standardError << ", expected "
            << T * v.mean;
        EXPECT_GT(m.mean, 0.0);
    }
}

TEST_P(GridMediaRender, BeerLambertThroughTwoDensities) {
    expectBeerLambert(GetParam(), IntegratorKind::Path);
}

TEST_P(GridMediaRender, BeerLambertThroughTwoDensitiesSeenByLightTracing) {
    expectBeerLambert(GetParam(), IntegratorKind::Light);
}

// The same slab emitting: along a ray without scattering the radiance gained is
// Le (1 - T) whatever the density profile (dL/dz = sigma_a(z) (Le - L)), so the pixel is
// Le_behind T + Le (1 - T): the emission estimated at every tentative collision, over the
// channels' average of its densities (path tracing; light tracing and BDPT refuse emitting
// media). RGB mode, where the pixel is exactly this per channel.
TEST(GridMediaRenderRgb, EmissionOfAnAbsorbingSlab) {
    const Rgb<double> sigma(0.2, 0.7, 1.5), Le(0.5, 1.0, 2.0), behind(2.0, 1.0, 0.5);
    const Rendered r = render(sceneFromText(gridSlab("[0.2, 0.7, 1.5]", R"(, "Le": [0.5, 1, 2])")),
                              RenderModeKind::Rgb, 256, 9);
    for (int c = 0; c < 3; ++c) {
        const double T = std::exp(-sigma[c] * 0.5 * (0.4 + 1.6) * 1.5);
        const double expected = behind[c] * T + Le[c] * (1.0 - T);
        const ImageMean& m = r.channel[c];
        EXPECT_LT(std::abs(m.mean - expected), kZ * m.standardError + 1e-6)
            << "channel " << c << ": " << m.mean << " +- " << m.standardError << ", expected "
            << expected;
    }
}

// A chromatic medium in an index-matched sphere over a floor, lit by a rectangle lamp.
std::string chromaticSphere(const std::string& medium) {
    return R"({
      "camera": {"position": [0, 1, -4], "look_at": [0, 0.3, 0], "fov": 45},
      "film": {"resolution": [12, 12]},
      "integrator": {"max_depth": 200},
      "media": {"dye": )" +
           medium + R"(},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.6},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "sphere", "center": [0, 0.5, 0], "radius": 1, "material": "interface",
         "interior": "dye"},
        {"type": "rectangle", "material": "floor",
         "transform": [{"scale": 4}, {"rotate": {"axis": [1, 0, 0], "angle": -90}},
                       {"translate": [0, -0.5, 0]}]},
        {"type": "rectangle", "material": "lamp", "emission": {"radiance": 4},
         "transform": [{"scale": 1.5}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"translate": [0.5, 3, 0]}]}]})";
}

constexpr const char* kDye = R"("sigma_a": [0.1, 0.6, 1.5], "sigma_s": [2.5, 1.0, 0.3], "g": 0.5)";

TEST_P(GridMediaRender, ConstantGridEqualsTheHomogeneousMedium) {
    const SceneDesc homogeneous =
        sceneFromText(chromaticSphere(std::string(R"({"type": "homogeneous", )") + kDye + "}"));
    SceneDesc grid = sceneFromText(chromaticSphere(
        std::string(R"({"type": "grid", "density": {"size": [2, 2, 2], "values": [1, 1, 1, 1, 1,
                    1, 1, 1]}, "bounds": {"min": [-1.1, -0.6, -1.1], "max": [1.1, 1.6, 1.1]}, )") +
        kDye + "}"));
    replaceGrid(grid, 0, scaledMajorants(*grid.media[0].grid, 1.5f));
    const Rendered a = render(homogeneous, GetParam(), 256, 5);
    const Rendered b = render(grid, GetParam(), 256, 6);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(a.channel[c].mean, 0.01) << "channel " << c << " renders black";
        EXPECT_LT(std::abs(welch(a.channel[c], b.channel[c])), kZ)
            << "channel " << c << ": homogeneous " << a.channel[c].mean << " +- "
            << a.channel[c].standardError << ", grid " << b.channel[c].mean << " +- "
            << b.channel[c].standardError;
    }
}

// A slab of heterogeneous chromatic grid medium in front of a large lamp, densities close to
// their majorants (so that a null collision's light-sampling ratio sigma_maj / sigma_n is
// large): next-event estimation with ratio-tracked shadow rays and MIS over strategies and
// channels, against phase-function sampling alone.
const char* kGridSlabBeforeALamp = R"({
  "camera": {"position": [0.3, 0.2, -3], "look_at": [0, 0, 0.5], "fov": 40},
  "film": {"resolution": [12, 12]},
  "integrator": {"max_depth": 200},
  "media": {"slab": {"type": "grid", "sigma_a": [0.05, 0.1, 0.2], "sigma_s": [1, 1.5, 2],
                     "density": {"size": [3, 3, 3], "values": [0.8, 1, 0.9, 0.9, 1, 0.8, 1, 0.9,
                       0.8, 0.9, 1, 0.9, 1, 0.85, 1, 0.9, 1, 0.8, 0.8, 0.9, 1, 0.8, 1, 0.9, 1, 0.8,
                       0.9]},
                     "bounds": {"min": [-1, -1, 0], "max": [1, 1, 1]}}},
  "materials": {"black": {"type": "lambert", "reflectance": 0}},
  "shapes": [
    {"type": "rectangle", "material": "interface", "exterior": "slab",
     "transform": [{"scale": 2}, {"translate": [0, 0, 0]}]},
    {"type": "rectangle", "material": "interface", "interior": "slab",
     "transform": [{"scale": 2}, {"translate": [0, 0, 1]}]},
    {"type": "rectangle", "material": "black", "emission": {"radiance": [1, 2, 3]},
     "transform": [{"scale": 3}, {"rotate": {"axis": [1, 0, 0], "angle": 180}},
                   {"translate": [0, 0, 1.3]}]}]})";

TEST_P(GridMediaRender, NextEventAgreesWithPhaseSamplingThroughAGrid) {
    const SceneDesc scene = sceneFromText(kGridSlabBeforeALamp);
    const Rendered nee = render(scene, GetParam(), 128, 7);
    const Rendered reference = render(scene, GetParam(), 512, 8, IntegratorKind::Path, false);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(nee.channel[c].mean, 0.01) << "channel " << c << " renders black";
        EXPECT_LT(std::abs(welch(nee.channel[c], reference.channel[c])), kZ)
            << "channel " << c << ": NEE " << nee.channel[c].mean << " +- "
            << nee.channel[c].standardError << ", phase sampling alone "
            << reference.channel[c].mean << " +- " << reference.channel[c].standardError;
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, GridMediaRender,
                         ::testing::Values(RenderModeKind::Rgb, RenderModeKind::Spectral),
                         [](const ::testing::TestParamInfo<RenderModeKind>& p) {
                             return p.param == RenderModeKind::Rgb ? "Rgb" : "Spectral";
                         });

}  // namespace
}  // namespace lamina::render
