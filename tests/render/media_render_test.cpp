// Renders through homogeneous media with known answers (docs/media.md), in RGB and spectral
// mode. Means are compared with z-tests on the film's per-pixel, per-channel variance
// estimates (the pixels are independent estimates): |z| < 3.29, two-sided significance 0.001 per
// channel and comparison, fixed seeds. Two renders are compared by Welch's test on their image
// means.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/math.h"
#include "media_render_helpers.h"

namespace lamina::render {
namespace {

using testing::ImageMean;
using testing::Rendered;
using testing::sceneFromText;
using testing::welch;

constexpr double kZ = 3.29;  // two-sided significance 0.001

Rendered render(const SceneDesc& scene, RenderModeKind mode, int spp, std::uint64_t seed,
                bool nextEvent = true, IntegratorKind integrator = IntegratorKind::Path) {
    return testing::renderMeans(scene, mode, spp, seed, nextEvent, integrator);
}

class MediaRender : public ::testing::TestWithParam<RenderModeKind> {};

// A slab 1.5 thick between two index-matched planes, seen by an orthographic camera along its
// normal in front of an emitter: every camera ray crosses exactly d = 1.5 of the medium, so
// the pixel is Le exp(-sigma_t d) (Beer-Lambert). RGB mode takes a chromatic absorber;
// spectral mode a grey one (an upsampled chromatic coefficient varies over each channel's
// wavelengths, and the film's colour is no longer exp of the RGB coefficient), compared with
// the same render without the medium.
std::string slab(const std::string& medium) {
    return R"({
      "camera": {"type": "orthographic", "position": [0, 0, -2], "look_at": [0, 0, 0]},
      "film": {"resolution": [8, 8]},
      "media": {"slab": )" +
           medium + R"(},
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
    const double d = 1.5;
    const Rgb<double> sigma =
        mode == RenderModeKind::Rgb ? Rgb<double>(0.2, 0.7, 1.5) : Rgb<double>(0.9);
    const std::string medium = R"({"type": "homogeneous", "sigma_a": [)" +
                               std::to_string(sigma[0]) + ", " + std::to_string(sigma[1]) + ", " +
                               std::to_string(sigma[2]) + "]}";
    const Rendered withMedium = render(sceneFromText(slab(medium)), mode, 256, 3, true, integrator);
    const Rendered vacuum =
        render(sceneFromText(slab(R"({"type": "homogeneous"})")), mode, 64, 4, true, integrator);
    for (int c = 0; c < 3; ++c) {
        const ImageMean& v = vacuum.channel[c];
        if (mode == RenderModeKind::Rgb) {
            // Exact for the path integrator; light tracing's particles land on the film at
            // random.
            const double emitted = c == 0 ? 2 : c == 1 ? 1 : 0.5;
            EXPECT_NEAR(v.mean, emitted,
                        integrator == IntegratorKind::Path ? 1e-6 : kZ * v.standardError);
        }
        const double T = std::exp(-sigma[c] * d);
        const ImageMean& m = withMedium.channel[c];
        const double se = std::hypot(m.standardError, T * v.standardError);
        EXPECT_LT(std::abs(m.mean - T * v.mean), kZ * se + 1e-6)
            << "channel " << c << ": " << m.mean << " +- " << m.standardError << ", expected "
            << T * v.mean;
        EXPECT_GT(m.mean, 0.0);
    }
}

TEST_P(MediaRender, BeerLambertThroughAnAbsorbingSlab) {
    expectBeerLambert(GetParam(), IntegratorKind::Path);
}

// The same seen by light tracing: the particles leave the emitter in vacuum, and the camera
// connection of the emitter itself crosses the slab (the transmittance of a camera
// connection through index-matched interfaces).
TEST_P(MediaRender, BeerLambertThroughAnAbsorbingSlabSeenByLightTracing) {
    expectBeerLambert(GetParam(), IntegratorKind::Light);
}

// A white furnace with a medium: a closed sphere of radius 5 whose black walls emit
// radiance 1, around an index-matched sphere of an albedo-1 medium (chromatic extinction, so
// that spectral MIS is exercised; anisotropic). In equilibrium the radiance is 1 everywhere:
// the medium neither absorbs nor adds. With next-event estimation (light samples through the
// interface, MIS with the phase function) and without.
const char* kMediumFurnace = R"({
  "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 50},
  "film": {"resolution": [12, 12]},
  "integrator": {"max_depth": 1000},
  "media": {"fog": {"type": "homogeneous", "sigma_s": [0.5, 1.5, 4], "g": 0.6}},
  "materials": {"black": {"type": "lambert", "reflectance": 0}},
  "shapes": [
    {"type": "sphere", "radius": 5, "flip_normals": true, "material": "black",
     "emission": {"radiance": 1}},
    {"type": "sphere", "radius": 1.2, "material": "interface", "interior": "fog"}]})";

TEST_P(MediaRender, WhiteFurnaceKeepsEnergyWithAndWithoutNextEvent) {
    const SceneDesc scene = sceneFromText(kMediumFurnace);
    for (const bool nextEvent : {true, false}) {
        const Rendered r = render(scene, GetParam(), 1024, 5, nextEvent);
        for (int c = 0; c < 3; ++c) {
            const ImageMean& m = r.channel[c];
            EXPECT_LT(std::abs(m.mean - 1.0), kZ * m.standardError + 2e-4)
                << "next_event " << nextEvent << " channel " << c << ": " << m.mean << " +- "
                << m.standardError;
        }
    }
}

// A chromatic medium (extinction and albedo different in every channel) in an index-matched
// sphere over a diffuse floor, lit by a rectangle: next-event estimation through the
// interface with MIS, and the phase function alone, converge to the same image.
const char* kChromaticSphere = R"({
  "camera": {"position": [0, 1, -4], "look_at": [0, 0.3, 0], "fov": 45},
  "film": {"resolution": [16, 16]},
  "integrator": {"max_depth": 200},
  "media": {"dye": {"type": "homogeneous", "sigma_a": [0.1, 0.6, 1.5],
                    "sigma_s": [2.5, 1.0, 0.3], "g": 0.5}},
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

TEST_P(MediaRender, ChromaticMediumMeanIsTheSameWithAndWithoutNextEvent) {
    const SceneDesc scene = sceneFromText(kChromaticSphere);
    const Rendered nee = render(scene, GetParam(), 128, 6, true);
    const Rendered reference = render(scene, GetParam(), 1024, 7, false);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(nee.channel[c].mean, 0.01) << "channel " << c << " renders black";
        EXPECT_LT(std::abs(welch(nee.channel[c], reference.channel[c])), kZ)
            << "channel " << c << ": NEE " << nee.channel[c].mean << " +- "
            << nee.channel[c].standardError << ", phase sampling alone "
            << reference.channel[c].mean << " +- " << reference.channel[c].standardError;
    }
}

// The camera inside fog that fills the scene (no boundary: the camera's medium is everywhere),
// a diffuse floor and a rectangle light: next-event estimation from medium and surface
// vertices through the fog against the phase function and BSDF sampling alone.
const char* kCameraInFog = R"({
  "camera": {"position": [0, 1, -4], "look_at": [0, 0.5, 0], "fov": 50, "medium": "fog"},
  "film": {"resolution": [16, 16]},
  "integrator": {"max_depth": 200},
  "media": {"fog": {"type": "homogeneous", "sigma_a": 0.05, "sigma_s": [0.3, 0.2, 0.1],
                    "g": -0.3}},
  "materials": {"floor": {"type": "lambert", "reflectance": 0.5},
                "lamp": {"type": "lambert", "reflectance": 0}},
  "shapes": [
    {"type": "rectangle", "material": "floor",
     "transform": [{"scale": 5}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]},
    {"type": "rectangle", "material": "lamp", "emission": {"radiance": 3},
     "transform": [{"scale": 1.2}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                   {"translate": [0, 3, 0]}]}]})";

TEST_P(MediaRender, CameraInsideFogAgreesWithAndWithoutNextEvent) {
    const SceneDesc scene = sceneFromText(kCameraInFog);
    ASSERT_EQ(scene.camera.medium, 0);
    const Rendered nee = render(scene, GetParam(), 128, 8, true);
    const Rendered reference = render(scene, GetParam(), 1024, 9, false);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(nee.channel[c].mean, 0.01) << "channel " << c << " renders black";
        EXPECT_LT(std::abs(welch(nee.channel[c], reference.channel[c])), kZ)
            << "channel " << c << ": NEE " << nee.channel[c].mean << " +- "
            << nee.channel[c].standardError << ", phase sampling alone "
            << reference.channel[c].mean << " +- " << reference.channel[c].standardError;
    }
}

// Emission in a medium: a sphere of purely absorbing, emitting medium (sigma_a, Le) seen along
// its diameter from a black room. The radiance through a chord of length l is
// Le (1 - exp(-sigma_a l)); the centre pixel's chord is nearly the diameter, so its mean is
// bounded by that and by the chord through the pixel's far corner.
TEST_P(MediaRender, EmittingMediumGivesLeTimesOneMinusTransmittance) {
    const char* scene = R"({
      "camera": {"type": "orthographic", "position": [0, 0, -3], "look_at": [0, 0, 0],
                 "screen_window": [-0.01, 0.01, -0.01, 0.01]},
      "film": {"resolution": [1, 1]},
      "media": {"glow": {"type": "homogeneous", "sigma_a": 0.8, "Le": 1.5}},
      "materials": {"black": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "sphere", "radius": 1, "material": "interface", "interior": "glow"},
        {"type": "sphere", "radius": 10, "flip_normals": true, "material": "black",
         "emission": {"radiance": 0.000001}}]})";
    const Rendered r = render(sceneFromText(scene), GetParam(), 4096, 10);
    // The chord at the pixel's corner (0.01 sqrt 2 off axis) is 2 sqrt(1 - 0.0002) long.
    const double hi = 1.5 * (1 - std::exp(-0.8 * 2.0)) + 1e-6;
    const double lo = 1.5 * (1 - std::exp(-0.8 * 2.0 * std::sqrt(1 - 0.0002)));
    for (int c = 0; c < 3; ++c) {
        const ImageMean& m = r.channel[c];
        EXPECT_LT(m.mean,
                  hi + kZ * m.standardError + (GetParam() == RenderModeKind::Rgb ? 0 : 2e-3));
        EXPECT_GT(m.mean,
                  lo - kZ * m.standardError - (GetParam() == RenderModeKind::Rgb ? 0 : 2e-3));
    }
}

// The same emitting, absorbing sphere rendered whole by every integrator: light tracing starts
// particles in the gas's volume and connects their start points to the lens; BDPT counts the
// emission at its camera subpaths' medium vertices and joins light subpaths started in the
// volume, weighted by MIS (docs/media.md, "Emitting media in light tracing and BDPT"). An
// orthographic window of side w = 2.4 around the unit sphere: the image mean is the integral
// over the disk of Le (1 - exp(-2 sigma_a sqrt(1 - r^2))), over w^2; with u = sqrt(1 - r^2),
//   2 pi Le (1/2 - (1 - e^-b (1 + b)) / b^2) / w^2,  b = 2 sigma_a.
// The black room's emission (1e-6, so that the scene has a light) adds at most 1e-6.
TEST_P(MediaRender, EmittingMediumClosedFormByEveryIntegrator) {
    const char* scene = R"({
      "camera": {"type": "orthographic", "position": [0, 0, -3], "look_at": [0, 0, 0],
                 "screen_window": [-1.2, 1.2, -1.2, 1.2]},
      "film": {"resolution": [8, 8]},
      "media": {"glow": {"type": "homogeneous", "sigma_a": 0.8, "Le": 1.5}},
      "materials": {"black": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "sphere", "radius": 1, "material": "interface", "interior": "glow"},
        {"type": "sphere", "radius": 10, "flip_normals": true, "material": "black",
         "emission": {"radiance": 0.000001}}]})";
    const double b = 2 * 0.8, w = 2.4;
    const double expected =
        2 * kPi<double> * 1.5 * (0.5 - (1 - std::exp(-b) * (1 + b)) / (b * b)) / (w * w);
    const SceneDesc s = sceneFromText(scene);
    for (const auto& [integrator, spp] :
         {std::pair{IntegratorKind::Path, 256}, std::pair{IntegratorKind::Light, 2048},
          std::pair{IntegratorKind::Bdpt, 256}}) {
        const Rendered r = render(s, GetParam(), spp, 12, true, integrator);
        for (int c = 0; c < 3; ++c) {
            const ImageMean& m = r.channel[c];
            EXPECT_LT(std::abs(m.mean - expected),
                      kZ * m.standardError + 1e-6 + (GetParam() == RenderModeKind::Rgb ? 0 : 2e-3))
                << kIntegratorNames.name(integrator) << " channel " << c << ": " << m.mean << " +- "
                << m.standardError << ", expected " << expected;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, MediaRender,
                         ::testing::Values(RenderModeKind::Rgb, RenderModeKind::Spectral),
                         [](const ::testing::TestParamInfo<RenderModeKind>& p) {
                             return std::string(kRenderModeNames.name(p.param));
                         });

}  // namespace
}  // namespace lamina::render
