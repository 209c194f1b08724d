// Polarised light-vs-camera reciprocity: camera path tracing, light tracing and BDPT in the
// polarised mode must converge to the same Stokes images S0..S3 (Mojzik, Skrivan, Wilkie and
// Krivanek, "Bi-Directional Polarised Light Transport", EGSR 2016). Light paths multiply the
// physical Mueller matrices in the order light meets them and camera paths in the reverse order
// (docs/polarisation.md, "Light paths"); a sign or frame error in either shows up in S1 or S2
// long before it moves S0; BDPT multiplies camera prefix, connection and light prefix. Each
// integrator renders the scene as 16 independent batches (64x64; 128 spp for path and bdpt,
// 512 particles per pixel for light); for each pair of integrators each Stokes component's
// luminance is compared with Welch's t-test on 4x4-pixel blocks at alpha = 0.01 and on the
// image mean, as in integrator_agreement_test.cpp: at most 3% of the blocks rejected and the
// means within three standard errors (p >= 0.0027). Broken once on purpose: light paths that
// use the camera path's matrices (evalMueller(wo, wi) in its own frames, not the physical
// event's) disagree on S1 and S2. The test first checks that S1 and S2 carry
// a signal (blocks far from zero), so that their agreement says something.
#include <gtest/gtest.h>

#include <array>

#include "lamina/experiments/estimator_agreement.h"
#include "render_helpers.h"
#include "source_files.h"

namespace lamina::render {
namespace {

using namespace lamina::experiments;

constexpr int kBatches = 16;
constexpr double kMaxBlockRejection = 0.03;
constexpr double kMeanPValue = 0.0027;  // three standard errors, two-sided

/// The four Stokes components of `batches` independent polarised renders.
std::array<BatchImages, 4> renderStokesBatches(const SceneDesc& scene, IntegratorKind integrator,
                                               int spp, std::uint64_t seed) {
    std::array<BatchImages, 4> images{BatchImages(64, 64), BatchImages(64, 64), BatchImages(64, 64),
                                      BatchImages(64, 64)};
    RenderOptions o;
    o.integrator = integrator;
    o.mode = RenderModeKind::Polarised;
    o.resolution = std::make_pair(64, 64);
    o.sampler = SamplerKind::Independent;
    o.spp = spp / kBatches;
    for (int k = 0; k < kBatches; ++k) {
        o.seed = seed * 1000 + std::uint64_t(k);
        const RenderResult r = renderScene(scene, o);
        for (int i = 0; i < 4; ++i)
            images[std::size_t(i)].addStokes(*r.film, i);
    }
    return images;
}

/// The number of 4x4 blocks whose mean is more than five standard errors from zero.
int significantBlocks(const BatchImages& image) {
    int n = 0;
    for (int y = 0; y < 64; y += 4)
        for (int x = 0; x < 64; x += 4) {
            const auto r = image.region(x, y, x + 4, y + 4);
            if (std::abs(r.mean) > 5.0 * std::sqrt(r.varianceOfMean)) ++n;
        }
    return n;
}

class PolarisedReciprocity : public ::testing::TestWithParam<const char*> {};

void expectAgreement(const std::array<BatchImages, 4>& a, const std::array<BatchImages, 4>& b,
                     const std::string& pair) {
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 4;
    for (int i = 0; i < 4; ++i) {
        const AgreementResult r = testAgreement(a[std::size_t(i)], b[std::size_t(i)], test);
        std::printf("  %-14s S%d: blocks %.2f%% rejected; means %+.5f and %+.5f, p %.4f\n",
                    pair.c_str(), i, 100 * r.blockRejectionRate(), r.meanA, r.meanB, r.meanPValue);
        // S0 has a value everywhere; S1 and S2 where light arrives polarised (blocks of
        // unpolarised light, exactly 0 in every batch, have nothing to test); S3 is nearly
        // zero in these scenes (no event turns linear light circular twice).
        if (i == 0) {
            EXPECT_EQ(r.blocksTested, 256) << pair << " S0";
        } else if (i < 3) {
            EXPECT_GE(r.blocksTested, 32) << pair << " S" << i;
        }
        EXPECT_LE(r.blockRejectionRate(), kMaxBlockRejection) << pair << " S" << i;
        EXPECT_GE(r.meanPValue, kMeanPValue)
            << pair << " S" << i << ": means " << r.meanA << " and " << r.meanB;
    }
}

TEST_P(PolarisedReciprocity, PathLightAndBdptAgreeOnEveryStokesComponent) {
    const SceneDesc scene = loadScene(testing::sourceFile(GetParam()).string());
    const auto path = renderStokesBatches(scene, IntegratorKind::Path, 128, 11);
    const auto light = renderStokesBatches(scene, IntegratorKind::Light, 512, 22);
    const auto bdpt = renderStokesBatches(scene, IntegratorKind::Bdpt, 128, 33);
    ASSERT_GT(path[0].region(0, 0, 64, 64).mean, 0.0) << "the scene renders black";
    // The scene polarises: S1 and S2 are visibly non-zero somewhere.
    EXPECT_GE(significantBlocks(path[1]) + significantBlocks(path[2]), 8);
    expectAgreement(path, light, "path vs light");
    expectAgreement(path, bdpt, "path vs bdpt");
    expectAgreement(light, bdpt, "light vs bdpt");
}

std::string sceneName(const ::testing::TestParamInfo<const char*>& p) {
    static const char* const kNames[] = {"RoughGold", "RoughGlass", "RoughLayered"};
    return kNames[p.index];
}

INSTANTIATE_TEST_SUITE_P(Scenes, PolarisedReciprocity,
                         ::testing::Values("scenes/reciprocity/rough-conductor.json",
                                           "scenes/reciprocity/rough-glass.json",
                                           "scenes/reciprocity/rough-layered.json"),
                         sceneName);

}  // namespace
}  // namespace lamina::render
