// Camera path tracing, light tracing and BDPT must converge to the same image (Helmholtz
// reciprocity and the adjoint transport, Veach 1997 chapters 3, 5 and 10). Each integrator
// renders a small scene of scenes/reciprocity/ as 32 independent batches (64x64, independent
// sampler, fixed seeds; 256 spp in all for path and bdpt, 1024 particles per pixel for light,
// whose splats are the most heavy-tailed); every pair is compared with Welch's t-test on 4x4-pixel
// blocks of the luminance at alpha = 0.01 (256 blocks) and on the image mean.
// Pass: at most 3% of the blocks rejected and the means within three standard errors (t-test
// p >= 0.0027). The per-pixel rejection rate is printed, not asserted: light tracing of glossy
// surfaces seen directly is heavy-tailed, which a t-test of one pixel over 32 batches does not
// tolerate (blocks of 16 pixels do).
// The break-it tests switch off the adjoint shading-normal correction, the transport-mode rule
// for refraction and the order of the BSDF's arguments at connections, and the check fails.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lamina/bsdf/conductor.h"
#include "lamina/experiments/estimator_agreement.h"
#include "render_helpers.h"
#include "rgl_file_writer.h"
#include "source_files.h"

namespace lamina::render {
namespace {

using namespace lamina::experiments;

struct AgreementCase {
    const char* name;
    const char* scene;  ///< relative to the source directory
    RenderModeKind mode;
    int blocks = 256;  ///< the 4x4 blocks that see something (a black sky is not tested)
};

std::string sourcePath(const std::string& relative) {
    return testing::sourceFile(relative).string();
}

BatchImages render(const SceneDesc& scene, IntegratorKind integrator, RenderModeKind mode,
                   std::uint64_t seed, const TransportAblations& ablations = {}) {
    RenderOptions o;
    o.integrator = integrator;
    o.mode = mode;
    o.seed = seed;
    o.resolution = std::make_pair(64, 64);
    o.ablations = ablations;
    return renderBatches(scene, o, integrator == IntegratorKind::Light ? 1024 : 256, 32);
}

AgreementResult compare(const BatchImages& a, const BatchImages& b) {
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 4;
    return testAgreement(a, b, test);
}

constexpr double kMaxBlockRejection = 0.03;
constexpr double kMeanPValue = 0.0027;  // three standard errors, two-sided

void expectAgreement(const AgreementResult& r, const std::string& pair, int blocks = 256) {
    std::printf("  %-14s pixels %.2f%%, blocks %.2f%% rejected; mean rel. diff %+.4f +- %.4f\n",
                pair.c_str(), 100 * r.pixelRejectionRate(), 100 * r.blockRejectionRate(),
                r.relativeDifference, r.standardError);
    EXPECT_EQ(r.blocksTested, blocks) << pair;
    EXPECT_LE(r.blockRejectionRate(), kMaxBlockRejection) << pair;
    EXPECT_GE(r.meanPValue, kMeanPValue)
        << pair << ": relative difference " << r.relativeDifference << " +- " << r.standardError;
}

void expectDisagreement(const AgreementResult& r) {
    EXPECT_TRUE(r.blockRejectionRate() > kMaxBlockRejection || r.meanPValue < kMeanPValue)
        << "blocks " << r.blockRejectionRate() << ", mean p " << r.meanPValue;
    EXPECT_FALSE(r.agree(0.01));
}

class IntegratorsAgree : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(IntegratorsAgree, PathLightAndBdptConvergeToTheSameImage) {
    const AgreementCase& c = GetParam();
    const SceneDesc scene = loadScene(sourcePath(c.scene));
    const BatchImages path = render(scene, IntegratorKind::Path, c.mode, 11);
    const BatchImages light = render(scene, IntegratorKind::Light, c.mode, 22);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, c.mode, 33);
    ASSERT_GT(path.region(0, 0, 64, 64).mean, 0.0) << "the scene renders black";
    expectAgreement(compare(path, light), "path vs light", c.blocks);
    expectAgreement(compare(path, bdpt), "path vs bdpt", c.blocks);
    expectAgreement(compare(light, bdpt), "light vs bdpt", c.blocks);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, IntegratorsAgree,
    ::testing::Values(
        AgreementCase{"CornellBox", "scenes/cornell-box.json", RenderModeKind::Rgb},
        AgreementCase{"RoughConductorAndSpot", "scenes/reciprocity/rough-conductor.json",
                      RenderModeKind::Rgb},
        AgreementCase{"RoughGlass", "scenes/reciprocity/rough-glass.json", RenderModeKind::Rgb},
        AgreementCase{"ShadingNormalsAndMeshLight", "scenes/reciprocity/smooth-normals.json",
                      RenderModeKind::Rgb},
        AgreementCase{"DispersiveGlassSpectral", "scenes/reciprocity/dispersive-glass.json",
                      RenderModeKind::Spectral},
        AgreementCase{"EnvironmentAndSun", "scenes/reciprocity/environment.json",
                      RenderModeKind::Rgb},
        AgreementCase{"InstancesAndCutOuts", "scenes/reciprocity/cutouts.json",
                      RenderModeKind::Rgb},
        AgreementCase{"OrthographicCamera", "scenes/reciprocity/orthographic.json",
                      RenderModeKind::Rgb},
        AgreementCase{"BumpAndNormalMaps", "scenes/reciprocity/bump-and-normal-maps.json",
                      RenderModeKind::Rgb},
        AgreementCase{"Quadrics", "scenes/reciprocity/quadrics.json", RenderModeKind::Rgb},
        AgreementCase{"MotionBlur", "scenes/reciprocity/motion.json", RenderModeKind::Rgb},
        // Paths that bounce on an emitting rectangle's own surface (its next-event estimation
        // from its own plane).
        AgreementCase{"ReflectingLampBeforeAWall", "scenes/reciprocity/lamp-before-wall.json",
                      RenderModeKind::Rgb},
        // A sky seen only through a window (a portal): next-event samples through it, particles
        // start on it.
        AgreementCase{"PortalWindow", "scenes/reciprocity/portal-window.json", RenderModeKind::Rgb},
        // Curves of the hair material: a BSDF that is not reciprocal, light crossing tubes;
        // 189 blocks see the floor and the hair (the sky above is black).
        AgreementCase{"Hair", "scenes/hair-tufts.json", RenderModeKind::Rgb, 189}),
    [](const ::testing::TestParamInfo<AgreementCase>& p) { return std::string(p.param.name); });

/// Path tracing against `integrator` with one deliberate mistake switched on: must disagree.
void expectBrokenDisagrees(const char* scenePath, IntegratorKind integrator,
                           bool TransportAblations::*mistake) {
    const SceneDesc scene = loadScene(sourcePath(scenePath));
    TransportAblations broken;
    broken.*mistake = true;
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages other = render(scene, integrator, RenderModeKind::Rgb, 22, broken);
    expectDisagreement(compare(path, other));
}

// Break it once: without the adjoint correction light tracing disagrees with path tracing on
// the faceted sphere with smooth normals (pbrt-v3 issue 73).
// The random-walk coated material: eval and pdf are estimates, sample an exact path. The MIS
// weights of path and bdpt see the estimated pdf (docs/bsdf.md, "coated"); if that made MIS
// biased, path (NEE + BSDF sampling) would disagree with light tracing (no BSDF pdf at all).
// Smaller than the scenes above to stay fast: 32x32 pixels, 2x2-pixel blocks (256, of which
// the 180 that see the objects are tested).
TEST(IntegratorsAgree, OnCoatedObjects) {
    const SceneDesc scene = loadScene(sourcePath("scenes/reciprocity/coated.json"));
    const auto renderCoated = [&](IntegratorKind integrator, std::uint64_t seed) {
        RenderOptions o;
        o.integrator = integrator;
        o.mode = RenderModeKind::Rgb;
        o.seed = seed;
        return renderBatches(scene, o, integrator == IntegratorKind::Light ? 2048 : 512, 32);
    };
    const BatchImages path = renderCoated(IntegratorKind::Path, 11);
    const BatchImages light = renderCoated(IntegratorKind::Light, 22);
    const BatchImages bdpt = renderCoated(IntegratorKind::Bdpt, 33);
    ASSERT_GT(path.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 2;
    // The blocks of the black background are not tested.
    expectAgreement(testAgreement(path, light, test), "path vs light", 180);
    expectAgreement(testAgreement(path, bdpt, test), "path vs bdpt", 180);
    expectAgreement(testAgreement(light, bdpt, test), "light vs bdpt", 180);
}

// MIS with the coated material's estimated pdf against a reference that uses no pdf at all:
// path tracing with next-event estimation and MIS, and path tracing by BSDF sampling alone
// (`next_event` false: every emitter hit counts in full), on the coated scene without its spot
// light (no ray can hit a delta light). The same blockwise Welch test at alpha = 0.01, plus
// the binomial p-value of the number of rejected blocks (>= 0.001) and the image means within
// three standard errors. Breaking the MIS weights once on purpose (the BSDF sample of a coated
// surface weighted with twice its pdf, the light sample with the true one, so that the two
// weights of a path no longer sum to one) made it fail: MIS 2.9% brighter, six standard errors
// (docs/integrators.md).
TEST(IntegratorsAgree, OnCoatedObjectsMisMatchesBsdfSamplingAlone) {
    SceneDesc scene = loadScene(sourcePath("scenes/reciprocity/coated.json"));
    scene.lights.clear();
    SceneDesc reference = scene;
    reference.settings.nextEvent = false;
    RenderOptions o;
    o.integrator = IntegratorKind::Path;
    o.mode = RenderModeKind::Rgb;
    o.seed = 11;
    const BatchImages mis = renderBatches(scene, o, 512, 32);
    o.seed = 44;
    const BatchImages bsdfOnly = renderBatches(reference, o, 4096, 32);
    ASSERT_GT(mis.region(0, 0, 32, 32).mean, 0.0) << "the scene renders black";
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 2;
    const AgreementResult r = testAgreement(mis, bsdfOnly, test);
    expectAgreement(r, "MIS vs BSDF only", r.blocksTested);
    std::printf("  %d of %d blocks rejected, binomial p %.3f\n", r.blocksRejected, r.blocksTested,
                r.blockRejectionPValue(test.alpha));
    EXPECT_GT(r.blocksTested, 150);
    EXPECT_GE(r.blockRejectionPValue(test.alpha), 0.001);
}

// The key of that reference: read for `path` (default true), refused with the JSON path for the
// integrators that have no next-event estimation to turn off.
TEST(NextEventKey, IsReadForPathAndRefusedElsewhere) {
    const auto withIntegrator = [](const std::string& integrator) {
        return R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
                   "materials": {"m": {"type": "lambert"}},
                   "shapes": [{"type": "sphere", "material": "m"}],
                   "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 1}],
                   "integrator": )" +
               integrator + "}";
    };
    EXPECT_TRUE(testing::sceneFromText(withIntegrator(R"({"type": "path"})")).settings.nextEvent);
    EXPECT_FALSE(
        testing::sceneFromText(withIntegrator(R"({"next_event": false})")).settings.nextEvent);
    for (const char* other : {"light", "bdpt"}) {
        try {
            testing::sceneFromText(withIntegrator(std::string(R"({"type": ")") + other +
                                                  R"(", "next_event": false})"));
            ADD_FAILURE() << other << " took next_event";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(
                          "integrator.next_event: only the path integrator takes next_event"),
                      std::string::npos)
                << e.what();
        }
    }
}

TEST(IntegratorsAgreeBreakIt, WithoutTheAdjointCorrectionLightTracingDisagrees) {
    expectBrokenDisagrees("scenes/reciprocity/smooth-normals.json", IntegratorKind::Light,
                          &TransportAblations::noAdjointCorrection);
}

// ... and on bump- and normal-mapped surfaces, whose shading normals go through the same
// correction.
TEST(IntegratorsAgreeBreakIt, WithoutTheAdjointCorrectionLightTracingDisagreesOnBumpMaps) {
    expectBrokenDisagrees("scenes/reciprocity/bump-and-normal-maps.json", IntegratorKind::Light,
                          &TransportAblations::noAdjointCorrection);
}

// ... and with radiance's 1/eta^2 on light subpaths BDPT disagrees on the rough glass
// (pbrt-v4 issue 30). (Light tracing alone hides it there: for a closed object the factors of
// entering and leaving cancel.)
TEST(IntegratorsAgreeBreakIt, WithTheRadianceEtaRuleOnLightPathsBdptDisagrees) {
    expectBrokenDisagrees("scenes/reciprocity/rough-glass.json", IntegratorKind::Bdpt,
                          &TransportAblations::radianceOnLightPaths);
}

// ... and with the BSDF's arguments swapped at light-path connections, light tracing disagrees
// on the rough glass (refraction is lamina's one non-symmetric BSDF; pbrt-v4 issue 395).
TEST(IntegratorsAgreeBreakIt, WithSwappedDirectionsAtConnectionsLightTracingDisagrees) {
    expectBrokenDisagrees("scenes/reciprocity/rough-glass.json", IntegratorKind::Light,
                          &TransportAblations::swappedConnections);
}

// A mirroring transform of a mesh with vertex normals must flip its shading normals with its
// geometric ones in every integrator (pbrt-v3 issue 229): the faceted sphere, mirrored.
TEST(IntegratorsAgree, OnAMirroredMeshWithVertexNormals) {
    std::ifstream in(sourcePath("scenes/reciprocity/smooth-normals.json"));
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string anchor = R"("name": "faceted sphere", "material": "clay",)";
    const auto at = json.find(anchor);
    ASSERT_NE(at, std::string::npos);
    json.insert(at + anchor.size(), R"( "transform": [{ "scale": [-1, 1, 1] }],)");
    const SceneDesc scene = testing::sceneFromText(json);
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages light = render(scene, IntegratorKind::Light, RenderModeKind::Rgb, 22);
    expectAgreement(compare(path, light), "path vs light");
}

// A measured material (docs/bsdf.md, "measured") whose table is not reciprocal: a rough gold
// conductor tabulated in the RGL layout, its values scaled by 0.3 + 0.7 cos(theta_o) per
// tabulated viewing angle, so that f(wo, wi) and f(wi, wo) differ by up to a factor 3. Light
// tracing agrees with path tracing only through the adjoint (measured.h); evaluating the
// radiance form on light paths instead (pbrt-v4's way) made path vs light disagree (checked).
TEST(IntegratorsAgree, OnAMeasuredMaterialThatIsNotReciprocal) {
    using Spec = Rgb<double>;
    const MicrofacetDistribution<double> d(NdfKind::Ggx, 0.25, 0.25);
    const ConductorBxdf<Spec> gold(MicrofacetReflectionLobe<Spec>(
        d, Fresnel<Spec>::conductor(Spec(0.18, 0.42, 1.37), Spec(3.42, 2.35, 1.77))));
    auto fields = testing::rglFields(gold, d, {});
    std::vector<float> theta;
    for (const auto& f : fields)
        if (f.name == "theta_i") {
            theta.resize(f.shape[0]);
            std::memcpy(theta.data(), f.data.data(), f.data.size());
        }
    for (auto& f : fields) {
        if (f.name != "rgb") continue;
        std::vector<float> v(f.data.size() / 4);
        std::memcpy(v.data(), f.data.data(), f.data.size());
        const std::size_t perTheta = v.size() / theta.size();
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] *= float(0.3 + 0.7 * std::cos(theta[i / perTheta]));
        std::memcpy(f.data.data(), v.data(), f.data.size());
    }
    const auto file = std::filesystem::temp_directory_path() /
                      ("lamina-measured-agreement-" + std::to_string(::getpid()) + ".bsdf");
    testing::writeTensorFile(file, fields);
    std::ifstream in(sourcePath("scenes/reciprocity/rough-conductor.json"));
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string conductor = R"({ "type": "conductor", "material": "Au", "roughness": 0.5 })";
    const auto at = json.find(conductor);
    ASSERT_NE(at, std::string::npos);
    json.replace(at, conductor.size(),
                 R"({ "type": "measured", "filename": ")" + file.string() + R"(" })");
    const SceneDesc scene = testing::sceneFromText(json);
    std::filesystem::remove(file);
    const BatchImages path = render(scene, IntegratorKind::Path, RenderModeKind::Rgb, 11);
    const BatchImages light = render(scene, IntegratorKind::Light, RenderModeKind::Rgb, 22);
    const BatchImages bdpt = render(scene, IntegratorKind::Bdpt, RenderModeKind::Rgb, 33);
    expectAgreement(compare(path, light), "path vs light");
    expectAgreement(compare(path, bdpt), "path vs bdpt");
}

}  // namespace
}  // namespace lamina::render
