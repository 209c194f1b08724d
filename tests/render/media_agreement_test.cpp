// Camera path tracing, light tracing and BDPT converge to the same image through homogeneous
// and grid media (docs/media.md; the chromatic cloud is a grid: delta tracking, and ratio
// tracking on every connection): the light integrator's free flights, medium vertices and camera
// connections with transmittance, and BDPT's medium vertices, connections through media and
// MIS weights, against the path integrator's. Each integrator renders a scene of scenes/media/
// as 32 independent batches at 32x32 pixels (fixed seeds; 256 samples per pixel in all for
// path, 1024 particles per pixel for light, whose splats are heavier-tailed, 128 for bdpt, whose
// samples cost more), compared pair by pair by Welch's t-test on 2x2-pixel blocks of the
// luminance at alpha = 0.01 (256 blocks, as the integrator agreement tests compare them).
// Pass: at most 3% of the blocks rejected and the image means within three standard errors
// (two-sided p >= 0.0027).
// Broken once on purpose each (docs/media.md, "Tests"): without the camera connection's
// transmittance the fog slab fails (light 23% brighter), without the spectral MIS weight the
// clear-channel sphere fails (light 12% darker), and with particles started in the camera's
// medium the point light inside the absorber fails (light 46% brighter).
// BDPT, broken once each: without the connections' transmittance the fog slab fails (bdpt 43%
// brighter, 73% of the blocks rejected); without the spectral MIS weight the clear-channel
// sphere fails (bdpt 11% darker, 42%); with light subpaths started in the camera's medium the
// point light inside the absorber fails (bdpt 33% brighter, 80%); with a medium vertex's
// phase-function density left in solid angle in the MIS weights (not converted to area) all
// six scene cases fail (bdpt 9% to 18% off, 10% to 46% of the blocks).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lamina/experiments/estimator_agreement.h"
#include "render_helpers.h"
#include "source_files.h"

namespace lamina::render {
namespace {

using namespace lamina::experiments;

struct MediaCase {
    const char* name;
    const char* scene;  ///< relative to the source directory
    RenderModeKind mode;
    int samples = 1;  ///< times the samples per pixel of every integrator
};

BatchImages render(const SceneDesc& scene, IntegratorKind integrator, RenderModeKind mode,
                   std::uint64_t seed, const TransportAblations& ablations = {}, int samples = 1) {
    RenderOptions o;
    o.ablations = ablations;
    o.integrator = integrator;
    o.mode = mode;
    o.seed = seed;
    o.resolution = std::make_pair(32, 32);
    const int spp = integrator == IntegratorKind::Light  ? 1024
                    : integrator == IntegratorKind::Bdpt ? 128
                                                         : 256;
    return renderBatches(scene, o, spp * samples, 32);
}

constexpr double kMaxBlockRejection = 0.03;
constexpr double kMeanPValue = 0.0027;  // three standard errors, two-sided

AgreementResult compare(const BatchImages& a, const BatchImages& b) {
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 2;
    return testAgreement(a, b, test);
}

bool agrees(const AgreementResult& r) {
    return r.blockRejectionRate() <= kMaxBlockRejection && r.meanPValue >= kMeanPValue;
}

/// Compares two integrators' images, prints the numbers and expects agreement.
void expectAgreement(const BatchImages& a, const BatchImages& b, const std::string& pair,
                     int minBlocks = 0) {
    const AgreementResult r = compare(a, b);
    std::printf("  %-14s blocks %.2f%% rejected; mean rel. diff %+.4f +- %.4f\n", pair.c_str(),
                100 * r.blockRejectionRate(), r.relativeDifference, r.standardError);
    // Blocks that are black in both images (the background) are not tested.
    EXPECT_GT(r.blocksTested, minBlocks) << pair;
    EXPECT_TRUE(agrees(r)) << pair << ": blocks " << r.blockRejectionRate() << ", mean p "
                           << r.meanPValue << ", relative difference " << r.relativeDifference
                           << " +- " << r.standardError;
}

class MediaIntegratorsAgree : public ::testing::TestWithParam<MediaCase> {};

TEST_P(MediaIntegratorsAgree, PathLightAndBdptConvergeToTheSameImage) {
    const MediaCase& c = GetParam();
    const SceneDesc scene = loadScene(testing::sourceFile(c.scene).string());
    ASSERT_TRUE(scene.hasMedia());
    const BatchImages path = render(scene, IntegratorKind::Path, c.mode, 11, {}, c.samples);
    const BatchImages light = render(scene, IntegratorKind::Light, c.mode, 22, {}, c.samples);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, c.mode, 33, {}, c.samples);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    expectAgreement(path, light, "path vs light", 150);
    expectAgreement(path, bdpt, "path vs bdpt", 150);
    expectAgreement(light, bdpt, "light vs bdpt", 150);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, MediaIntegratorsAgree,
    ::testing::Values(
        MediaCase{"FogSlab", "scenes/media/fog-slab.json", RenderModeKind::Rgb},
        MediaCase{"FogSlabSpectral", "scenes/media/fog-slab.json", RenderModeKind::Spectral},
        MediaCase{"ChromaticSphere", "scenes/media/chromatic-sphere.json", RenderModeKind::Rgb},
        MediaCase{"ChromaticSphereSpectral", "scenes/media/chromatic-sphere.json",
                  RenderModeKind::Spectral},
        MediaCase{"CameraInFog", "scenes/media/camera-in-fog.json", RenderModeKind::Rgb},
        MediaCase{"CameraInFogSpectral", "scenes/media/camera-in-fog.json",
                  RenderModeKind::Spectral},
        MediaCase{"ChromaticCloud", "scenes/media/chromatic-cloud.json", RenderModeKind::Rgb},
        MediaCase{"ChromaticCloudSpectral", "scenes/media/chromatic-cloud.json",
                  RenderModeKind::Spectral},
        // The procedural cloud in spectral mode, and glowing in RGB mode below: its density
        // formula does not depend on the mode, whose handling of a chromatic medium the grid
        // cloud above tests in both (an RGB case of this scene took 42 s of CI).
        MediaCase{"ProceduralCloudSpectral", "scenes/media/procedural-cloud.json",
                  RenderModeKind::Spectral},
        MediaCase{"GlowingSphere", "scenes/media/glowing-sphere.json", RenderModeKind::Rgb},
        MediaCase{"GlowingSphereSpectral", "scenes/media/glowing-sphere.json",
                  RenderModeKind::Spectral},
        MediaCase{"GlowingCloudInFog", "scenes/media/glowing-cloud-in-fog.json",
                  RenderModeKind::Rgb},
        // The procedural cloud glowing: its emission weighed by the density formula.
        MediaCase{"GlowingProceduralCloud", "scenes/media/glowing-procedural-cloud.json",
                  RenderModeKind::Rgb},
        // Twice the samples: spectral BDPT's estimate of the glowing grid is heavy-tailed
        // enough at the usual counts that 3 to 4% of the blocks were rejected while the image
        // means agreed (bdpt / path 0.999 and 1.000 per channel at 2048 / 4096 samples).
        MediaCase{"GlowingCloudInFogSpectral", "scenes/media/glowing-cloud-in-fog.json",
                  RenderModeKind::Spectral, 2}),
    [](const ::testing::TestParamInfo<MediaCase>& p) { return std::string(p.param.name); });

// Spectral MIS (medium_transport.h) matters for bias, not only noise, when a channel has no
// extinction: a particle (or a BDPT sample) whose hero is that channel never scatters in the
// medium, so the single-hero estimator misses the other channels' scattered light. The chromatic
// sphere with red passing unattenuated (RGB mode: an RGB zero is not zero at every wavelength of an
// upsampled spectrum).
TEST(MediaIntegratorsAgree, ChromaticSphereWithAClearChannel) {
    std::ifstream in(testing::sourceFile("scenes/media/chromatic-sphere.json"));
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string coefficients = R"("sigma_a": [0.1, 0.6, 1.5], "sigma_s": [2.5, 1.0, 0.3])";
    const auto at = json.find(coefficients);
    ASSERT_NE(at, std::string::npos);
    json.replace(at, coefficients.size(), R"("sigma_a": [0, 0.6, 0.2], "sigma_s": [0, 1.5, 2.5])");
    const SceneDesc scene = testing::sceneFromText(json);
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages light = render(scene, IntegratorKind::Light, RenderModeKind::Rgb, 22);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, RenderModeKind::Rgb, 33);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    expectAgreement(path, light, "path vs light");
    expectAgreement(path, bdpt, "path vs bdpt");
}

// A point light at the centre of a sphere of chromatic absorber (the camera outside, in
// vacuum): light tracing finds the medium its particles start in by walking from the camera
// through the sphere's boundary (mediumAt), as BDPT's light subpaths do, the path
// integrator's shadow rays by crossing it.
// The medium only absorbs: a scattering medium around a point light gives next-event
// estimation infinite variance (a medium vertex at distance r from the light contributes
// 1 / r^2, with density r^2 dr), which a t-test cannot tolerate.
TEST(MediaIntegratorsAgree, PointLightInsideAMediumSphere) {
    const SceneDesc scene = testing::sceneFromText(R"({
      "camera": {"position": [0, 1, -4], "look_at": [0, 0.3, 0], "fov": 45},
      "integrator": {"max_depth": 64},
      "media": {"dye": {"type": "homogeneous", "sigma_a": [0.3, 0.7, 1.4]}},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.6}},
      "shapes": [
        {"type": "sphere", "center": [0, 0.5, 0], "radius": 1, "material": "interface",
         "interior": "dye"},
        {"type": "rectangle", "material": "floor",
         "transform": [{"scale": 4}, {"rotate": {"axis": [1, 0, 0], "angle": -90}},
                       {"translate": [0, -0.5, 0]}]}],
      "lights": [{"type": "point", "position": [0, 0.5, 0], "intensity": 4}]})");
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages light = render(scene, IntegratorKind::Light, RenderModeKind::Rgb, 22);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, RenderModeKind::Rgb, 33);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    expectAgreement(path, light, "path vs light");
    expectAgreement(path, bdpt, "path vs bdpt");
}

// The glowing sphere of scenes/media/glowing-sphere.json behind a smooth glass boundary instead
// of an index-matched one: BDPT's strategies through the glass (the camera subpath's medium
// vertices behind a refraction, light subpaths from the gas refracted out) against path
// tracing's. Light tracing cannot connect through the smooth glass in view (docs/integrators.md).
TEST(MediaIntegratorsAgree, GlowingSphereBehindGlass) {
    std::ifstream in(testing::sourceFile("scenes/media/glowing-sphere.json"));
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string boundary = R"("material": "interface", "interior": "glow")";
    const auto at = json.find(boundary);
    ASSERT_NE(at, std::string::npos);
    json.replace(at, boundary.size(), R"("material": "glass", "interior": "glow")");
    const std::string materials = R"("materials": {)";
    json.replace(json.find(materials), materials.size(),
                 R"("materials": {"glass": {"type": "dielectric", "ior": 1.33},)");
    const SceneDesc scene = testing::sceneFromText(json);
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, RenderModeKind::Rgb, 33);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    expectAgreement(path, bdpt, "path vs bdpt", 150);
}

// Spectral MIS over the wavelengths switched off (`--ablate media-spectral-mis`,
// TransportAblations::noMediaSpectralMis: every wavelength weighted by the hero's free-flight
// density alone) is a worse estimator, not a biased one, where every channel has extinction: each
// integrator without it converges to the image of path tracing with it, in spectral mode through
// the chromatic sphere. Broken once: weighting by wavelength 0's density instead of the hero's
// (a biased estimator) fails it.
TEST(MediaSpectralMis, WithoutItEveryIntegratorConvergesToTheSameImage) {
    const SceneDesc scene =
        loadScene(testing::sourceFile("scenes/media/chromatic-sphere.json").string());
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Spectral, 11);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    TransportAblations heroOnly;
    heroOnly.noMediaSpectralMis = true;
    for (const IntegratorKind integrator :
         {IntegratorKind::Path, IntegratorKind::Light, IntegratorKind::Bdpt}) {
        const BatchImages without =
            render(scene, integrator, RenderModeKind::Spectral, 44, heroOnly);
        expectAgreement(
            path, without,
            "path vs " + std::string(kIntegratorNames.name(integrator)) + " without spectral MIS",
            150);
    }
}

}  // namespace
}  // namespace lamina::render
