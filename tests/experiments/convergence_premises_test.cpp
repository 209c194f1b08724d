// The premises `lamina convergence` checks of its reference (convergence_premises.h): a
// reference of another mode, resolution, scene, max_depth or converging setting is refused,
// one without metadata is not checked, a rendered one is flagged; and the reference's noise
// floor, which adds to every measured relMSE and flattens the fitted slope.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/pcg32.h"
#include "lamina/experiments/convergence.h"
#include "lamina/output/render_metadata.h"

namespace lamina::experiments {
namespace {

using render::RenderModeKind;

/// A scene of a 16x8 film read from nowhere (its hash is of no file) and what a lamina
/// reference of it, rendered with its settings in `mode`, says of itself.
struct Fixture {
    render::SceneDesc scene;
    ReferenceFacts reference;
    Fixture() {
        scene.file = "premises-scene.json";
        scene.film.width = 16;
        scene.film.height = 8;
        reference.name = "ref.exr";
        reference.width = 16;
        reference.height = 8;
        reference.metadata = {{"lamina:mode", "rgb"},
                              {"lamina:scene_hash", render::sceneHash(scene)},
                              {"lamina:scene", "premises-scene.json"},
                              {"lamina:max_depth", std::to_string(scene.settings.maxDepth)},
                              {"lamina:integrator", "path"},
                              {"lamina:next_event", "1"}};
    }
    PremiseOutcome outcome(const std::string& check, RenderModeKind mode = RenderModeKind::Rgb,
                           const render::RenderOptions& measured = {}) const {
        for (const Premise& p : referencePremises(reference, scene, measured, mode))
            if (p.check == check) return p.outcome;
        ADD_FAILURE() << "no premise " << check;
        return PremiseOutcome::Holds;
    }
};

TEST(ConvergencePremises, AReferenceOfTheSameSettingsHoldsEveryCheck) {
    const Fixture f;
    for (const Premise& p : referencePremises(f.reference, f.scene, {}, RenderModeKind::Rgb))
        EXPECT_EQ(p.outcome, PremiseOutcome::Holds) << describePremise(p);
}

TEST(ConvergencePremises, RefusesAReferenceOfAnotherMode) {
    const Fixture f;
    EXPECT_EQ(f.outcome("mode", RenderModeKind::Spectral), PremiseOutcome::Refused);
    EXPECT_EQ(f.outcome("mode", RenderModeKind::Polarised), PremiseOutcome::Refused);
}

TEST(ConvergencePremises, RefusesAnotherResolutionUnlessTheRunsAreOverriddenToIt) {
    Fixture f;
    f.reference.width = 32;
    EXPECT_EQ(f.outcome("resolution"), PremiseOutcome::Refused);
    render::RenderOptions measured;
    measured.resolution = std::pair{32, 8};
    EXPECT_EQ(f.outcome("resolution", RenderModeKind::Rgb, measured), PremiseOutcome::Holds);
}

TEST(ConvergencePremises, RefusesAReferenceOfOtherSceneFiles) {
    Fixture f;
    f.reference.metadata["lamina:scene_hash"] = "0123456789abcdef";
    EXPECT_EQ(f.outcome("scene"), PremiseOutcome::Refused);
}

TEST(ConvergencePremises, RefusesAnotherMaxDepthUnlessTheRunsAreOverriddenToIt) {
    Fixture f;
    f.reference.metadata["lamina:max_depth"] = "3";
    EXPECT_EQ(f.outcome("max_depth"), PremiseOutcome::Refused);
    render::RenderOptions measured;
    measured.maxDepth = 3;
    EXPECT_EQ(f.outcome("max_depth", RenderModeKind::Rgb, measured), PremiseOutcome::Holds);
}

TEST(ConvergencePremises, RefusesNextEventOffOnlyWhereItMissesDeltaLights) {
    Fixture f;
    f.reference.metadata["lamina:next_event"] = "0";
    // Area lights only: BSDF sampling alone converges to the same image.
    EXPECT_EQ(f.outcome("integrator settings"), PremiseOutcome::Holds);
    f.scene.lights.push_back(render::PointLightDesc{});
    EXPECT_EQ(f.outcome("integrator settings"), PremiseOutcome::Refused);
}

TEST(ConvergencePremises, AnotherRenderersImageIsNotCheckedButItsSizeIs) {
    Fixture f;
    f.reference.metadata.clear();
    for (const char* check : {"mode", "scene", "max_depth", "integrator settings"})
        EXPECT_EQ(f.outcome(check), PremiseOutcome::NotChecked) << check;
    EXPECT_EQ(f.outcome("resolution"), PremiseOutcome::Holds);
}

TEST(ConvergencePremises, ARenderedReferenceIsFlaggedAsSelfRendered) {
    Fixture f;
    f.reference.source = ReferenceSource::Rendered;
    const std::vector<Premise> p = referencePremises(f.reference, f.scene, {}, RenderModeKind::Rgb);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].check, "reference");
    EXPECT_EQ(p[0].outcome, PremiseOutcome::Flagged);
    EXPECT_NE(p[0].detail.find("self-rendered"), std::string::npos);
}

// A lamina reference with the measured renders' sampler and seed is correlated with them; with
// sobol-global (one film-position pattern for every seed) whatever the seeds, with sobol only
// at the same seed.
TEST(ConvergencePremises, ASobolGlobalReferenceIsCorrelatedWhateverTheSeeds) {
    const Fixture f;
    const auto reference = [](const std::string& sampler, const std::string& seed) {
        render::RgbImage image;
        image.metadata = {{"lamina:sampler", sampler}, {"lamina:seed", seed}};
        return image;
    };
    render::RenderOptions measured;
    measured.seed = 2;
    measured.sampler = render::SamplerKind::SobolGlobal;
    const auto correlated = referenceCorrelation(reference("sobol-global", "1"), f.scene, measured);
    ASSERT_TRUE(correlated.has_value());
    EXPECT_NE(correlated->find("sobol-global"), std::string::npos) << *correlated;
    EXPECT_FALSE(referenceCorrelation(reference("sobol", "1"), f.scene, measured));
    measured.sampler = render::SamplerKind::Sobol;
    EXPECT_FALSE(referenceCorrelation(reference("sobol", "1"), f.scene, measured));
    EXPECT_FALSE(referenceCorrelation(reference("sobol-global", "2"), f.scene, measured));
    EXPECT_TRUE(referenceCorrelation(reference("sobol", "2"), f.scene, measured));
}

/// A standard normal number (Box and Muller 1958).
double gaussian(Pcg32& rng) {
    const double u1 = 1.0 - rng.nextDouble(), u2 = rng.nextDouble();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}

// The floor is what the reference's noise adds to a measured relMSE: an image with noise of
// its own, scored against a noisy reference, measures its relMSE against the truth plus the
// floor. The relMSE divides by the noisy reference, which biases the mean of the squared
// noise by a factor 1 + 9 (sigma / value)^2 (second order in 1 / (value + noise)^2); with
// sigma 1-4% of the value that is under 1%. 3 x 10^5 values: the sample means' relative
// standard error is about 0.3%, the tolerance 2% (over 6 standard errors). Fixed seed.
TEST(ReferenceNoise, TheFloorIsWhatTheReferencesNoiseAddsToTheMeasuredRelMse) {
    Pcg32 rng(2024);
    render::RgbImage truth, reference, image;
    truth.width = reference.width = image.width = 320;
    truth.height = reference.height = image.height = 320;
    std::vector<float> variance;
    for (int i = 0; i < 320 * 320 * 3; ++i) {
        const double t = 0.5 + 1.5 * rng.nextDouble();
        const double sigmaRef = t * (0.01 + 0.03 * rng.nextDouble());
        const double sigmaImage = 0.03 * t;
        truth.pixels.push_back(float(t));
        reference.pixels.push_back(float(t + sigmaRef * gaussian(rng)));
        image.pixels.push_back(float(t + sigmaImage * gaussian(rng)));
        variance.push_back(float(sigmaRef * sigmaRef));
    }
    const double floor = referenceNoiseFloor(reference.pixels, variance);
    const double exactAgainstNoisy = compareImages(truth, reference).relmse;
    EXPECT_NEAR(floor / exactAgainstNoisy, 1.0, 0.02);
    const double measured = compareImages(image, reference).relmse;
    const double trueError = compareImages(image, truth).relmse;
    EXPECT_NEAR((trueError + floor) / measured, 1.0, 0.02);
}

TEST(ReferenceNoise, LeavesOutValuesThatAreNotFiniteAndIsNanWithoutAny) {
    EXPECT_DOUBLE_EQ(referenceNoiseFloor({1.0f, NAN, 0.0f}, {0.0101f, 1.0f, -1.0f}),
                     0.0101f / (1.0 + kRelMseEpsilon));
    EXPECT_TRUE(std::isnan(referenceNoiseFloor({NAN}, {1.0f})));
}

// The share: measured relMSE m(t) = a / t + f with the floor f at kMaxReferenceNoiseShare of the
// final m: the slope fitted over the run lies between the estimator's -1 and the end's -0.9.
TEST(ReferenceNoise, AtTheAllowedShareTheFittedSlopeIsFlattenedByLessThanItsShare) {
    const double a = 1.0, end = 100;
    const double f = kMaxReferenceNoiseShare / (1 - kMaxReferenceNoiseShare) * a / end;
    std::vector<ErrorLog::Row> rows;
    for (int k = 1; k <= 100; ++k) {
        ErrorLog::Row r{double(k), k, {}};
        r.metrics.relmse = a / k + f;
        rows.push_back(r);
    }
    EXPECT_NEAR(f / rows.back().metrics.relmse, kMaxReferenceNoiseShare, 1e-12);
    const double slope = fittedSlope(rows);
    EXPECT_GT(slope, -1.0);
    EXPECT_LT(slope, -(1 - kMaxReferenceNoiseShare));
}

TEST(ReferenceNoise, ATooNoisyGivenReferenceIsRefusedUnlessAllowedAndARenderedOneFlagged) {
    ReferenceFacts r;
    r.noiseFloor = 0.02;
    r.noiseSource = "Variance.R/G/B channels";
    EXPECT_EQ(noisePremise(r, 1.0, false).outcome, PremiseOutcome::Holds);
    EXPECT_EQ(noisePremise(r, 0.1, false).outcome, PremiseOutcome::Refused);
    EXPECT_NE(noisePremise(r, 0.1, false).detail.find("--allow-noisy-reference"),
              std::string::npos);
    EXPECT_EQ(noisePremise(r, 0.1, true).outcome, PremiseOutcome::Flagged);
    r.source = ReferenceSource::Rendered;
    EXPECT_EQ(noisePremise(r, 0.1, false).outcome, PremiseOutcome::Flagged);
    r.noiseFloor.reset();
    EXPECT_EQ(noisePremise(r, 0.1, false).outcome, PremiseOutcome::NotChecked);
}

}  // namespace
}  // namespace lamina::experiments
