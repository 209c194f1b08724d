// Every experiment that renders keeps its finished renders (kept_renders.h) and resumes from
// them. For each of fresnel --scene, layering --scene, reciprocity and polarisation: a run
// interrupted after its first render (the interrupt flag raised by the progress sink when the
// second render is announced, as SIGINT raises it: deterministic, no timing) keeps that render
// and names it with the way to resume; the resumed run takes it back, renders the rest, and
// reports exactly the numbers of an uninterrupted run with the same seed (renders are
// deterministic per seed, and both runs compute from the films as kept); a resume against
// renders of other settings is refused on one line naming the setting. `stability` keeps its
// audits as well as its scene renders.
#include "lamina/experiments/kept_renders.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/layering.h"
#include "lamina/experiments/polarisation.h"
#include "lamina/experiments/reciprocity.h"
#include "lamina/experiments/stability.h"
#include "scratch_directory.h"
#include "source_files.h"

namespace lamina::experiments {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

/// A progress sink that raises the interrupt flag at the `n`-th message containing `marker`,
/// and records every message.
struct Interrupter {
    std::string marker;
    int n = 2;
    std::shared_ptr<std::string> log = std::make_shared<std::string>();
    ProgressSink sink() const {
        auto seen = std::make_shared<int>(0);
        return [marker = marker, n = n, log = log, seen](const std::string& text) {
            *log += text;
            if (text.find(marker) != std::string::npos && ++*seen == n)
                render::renderInterruptFlag().store(true);
        };
    }
};

/// Runs `run(progress)` interrupted at the `n`-th message containing `marker` (by default the
/// second render announced); the Interrupted it throws.
template <typename Run>
Interrupted interruptAtSecondRender(Run&& run, const std::string& marker = "rendering ",
                                    int n = 2) {
    const Interrupter at{marker, n};
    try {
        run(at.sink());
    } catch (Interrupted& stopped) {
        render::renderInterruptFlag().store(false);
        return stopped;
    }
    render::renderInterruptFlag().store(false);
    ADD_FAILURE() << "not interrupted; progress:\n" << *at.log;
    return {};
}

class ExperimentResume : public lamina::testing::ScratchDirectoryTest {
  protected:
    /// The kept files and the partial data of the interruption, checked.
    void expectKeptOne(const Interrupted& stopped, const std::string& firstRender) {
        const std::filesystem::path file = dir_ / "interrupted" / keptRenderFile(firstRender);
        EXPECT_EQ(stopped.kept, file.string() +
                                    " (the same command with --resume continues from them "
                                    "without rendering them again)");
        EXPECT_TRUE(std::filesystem::exists(file));
        ASSERT_TRUE(stopped.partial.has_value());
        const auto& dict = std::get<Data::Dict>(stopped.partial->value());
        ASSERT_EQ(dict.size(), 1u);
        const auto& renders = std::get<Data::List>(dict[0].value.value());
        EXPECT_EQ(renders.size(), 1u);
    }
    std::filesystem::path interrupted() const { return dir_ / "interrupted"; }
    std::filesystem::path whole() const { return dir_ / "whole"; }
};

std::string refusal(const std::function<void()>& f) {
    const std::string message = lamina::testing::errorOf(f);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
}

TEST_F(ExperimentResume, PolarisationResumesFromItsKeptRendersWithTheSameNumbers) {
    PolarisationInputs in;
    in.scene = lamina::testing::sourceFile("scenes/polarisation/two-mirrors.json").string();
    in.spp = 4;
    in.keepDirectory = whole();
    const PolarisationResult uninterrupted = runPolarisation(in);

    in.keepDirectory = interrupted();
    const Interrupted stopped = interruptAtSecondRender([&](const ProgressSink& progress) {
        PolarisationInputs run = in;
        run.progress = progress;
        runPolarisation(run);
    });
    expectKeptOne(stopped, "polarised");

    in.resume = true;
    std::string log;
    in.progress = [&](const std::string& text) { log += text; };
    const PolarisationResult resumed = runPolarisation(in);
    EXPECT_THAT(log, HasSubstr("mode: kept from renders/polarised.exr"));
    EXPECT_THAT(log, Not(HasSubstr("rendering " + in.scene + " in polarised mode...")));
    for (AgainstPolarised PolarisationResult::*mode :
         {&PolarisationResult::spectral, &PolarisationResult::rgb}) {
        const AgainstPolarised& u = uninterrupted.*mode;
        const AgainstPolarised& v = resumed.*mode;
        for (const auto& [a, b] : {std::pair{u.meanRelative, v.meanRelative},
                                   {u.p95Relative, v.p95Relative},
                                   {u.meanDeltaE, v.meanDeltaE},
                                   {u.p95DeltaE, v.p95DeltaE}}) {
            EXPECT_EQ(a.value, b.value);
            EXPECT_EQ(a.floor, b.floor);
            EXPECT_EQ(a.otherSeed, b.otherSeed);
        }
        EXPECT_EQ(u.metrics.relmse, v.metrics.relmse);
    }
    EXPECT_EQ(uninterrupted.meanDolp, resumed.meanDolp);
    EXPECT_EQ(uninterrupted.dolpNoise, resumed.dolpNoise);

    in.overrides.seed = 99;
    EXPECT_THAT(refusal([&] { runPolarisation(in); }),
                HasSubstr(", this run asks for seed=99: resume with the same options"));
    in.overrides.seed.reset();
    in.spp = 8;
    EXPECT_THAT(refusal([&] { runPolarisation(in); }),
                HasSubstr("polarised.exr: rendered with spp=4, this run asks for spp=8"));
}

TEST_F(ExperimentResume, FresnelSceneResumesFromItsKeptRendersWithTheSameNumbers) {
    FresnelInputs in;
    in.materials = {"Au"};
    in.scene = lamina::testing::sourceFile("scenes/fresnel-spheres.json").string();
    in.spp = 2;
    in.overrides.resolution = {24, 16};
    in.keepDirectory = whole();
    const FresnelSceneComparison uninterrupted = *runFresnel(in).scene;

    in.keepDirectory = interrupted();
    const Interrupted stopped = interruptAtSecondRender([&](const ProgressSink& progress) {
        FresnelInputs run = in;
        run.progress = progress;
        runFresnel(run);
    });
    expectKeptOne(stopped, "scene_rgb");

    in.resume = true;
    std::string log;
    in.progress = [&](const std::string& text) { log += text; };
    const FresnelSceneComparison resumed = *runFresnel(in).scene;
    EXPECT_THAT(log, HasSubstr("in RGB mode: kept from renders/scene_rgb.exr"));
    EXPECT_EQ(uninterrupted.meanDeltaE, resumed.meanDeltaE);
    EXPECT_EQ(uninterrupted.p95DeltaE, resumed.p95DeltaE);
    EXPECT_EQ(uninterrupted.maxDeltaE, resumed.maxDeltaE);
    EXPECT_EQ(uninterrupted.floorMeanDeltaE, resumed.floorMeanDeltaE);
    EXPECT_EQ(uninterrupted.floorP95DeltaE, resumed.floorP95DeltaE);

    in.overrides.resolution = {20, 16};
    EXPECT_THAT(refusal([&] { runFresnel(in); }),
                HasSubstr("scene_rgb.exr: rendered with resolution=24x16, this run asks for "
                          "resolution=20x16"));
}

TEST_F(ExperimentResume, LayeringSceneResumesFromItsKeptRendersWithTheSameNumbers) {
    LayeringInputs in;
    in.materials = {"varnished-wood"};
    in.estimates = 16;
    in.albedoSamples = 64;
    in.scene = lamina::testing::sourceFile("scenes/layering/test-object.json").string();
    in.spp = 2;
    in.resolution = {16, 16};
    in.keepDirectory = whole();
    const LayeringResult uninterrupted = runLayering(in);

    in.keepDirectory = interrupted();
    const Interrupted stopped = interruptAtSecondRender([&](const ProgressSink& progress) {
        LayeringInputs run = in;
        run.progress = progress;
        runLayering(run);
    });
    expectKeptOne(stopped, "varnished-wood_walk_rgb");

    in.resume = true;
    const LayeringResult resumed = runLayering(in);
    const LayeringMaterialResult& a = uninterrupted.materials.at(0);
    const LayeringMaterialResult& b = resumed.materials.at(0);
    ASSERT_EQ(a.walkNoise.size(), b.walkNoise.size());
    for (std::size_t k = 0; k < a.walkNoise.size(); ++k) {
        EXPECT_EQ(a.walkNoise[k].meanDeltaE, b.walkNoise[k].meanDeltaE);
        EXPECT_EQ(a.walkNoise[k].p95DeltaE, b.walkNoise[k].p95DeltaE);
    }
    ASSERT_EQ(a.twins.size(), b.twins.size());
    for (std::size_t t = 0; t < a.twins.size(); ++t)
        for (std::size_t k = 0; k < a.twins[t].renderErrors.size(); ++k) {
            EXPECT_EQ(a.twins[t].renderErrors[k].meanDeltaE, b.twins[t].renderErrors[k].meanDeltaE);
            EXPECT_EQ(a.twins[t].renderErrors[k].p95DeltaE, b.twins[t].renderErrors[k].p95DeltaE);
        }

    in.seed = 7;
    EXPECT_THAT(refusal([&] { runLayering(in); }),
                HasSubstr("varnished-wood_walk_rgb.exr: rendered with seed=1, this run asks for "
                          "seed=7"));
}

TEST_F(ExperimentResume, ReciprocityResumesFromItsKeptBatchesWithTheSameNumbers) {
    ReciprocityInputs in;
    in.scene = lamina::testing::sourceFile("scenes/reciprocity/rough-conductor.json").string();
    in.integrators = {render::IntegratorKind::Path, render::IntegratorKind::Light};
    in.spp = 8;
    in.batches = 4;
    in.overrides.resolution = {16, 16};
    in.keepDirectory = whole();
    const ReciprocityResult uninterrupted = runReciprocity(in);

    in.keepDirectory = interrupted();
    // The batches report "path: batch 1/4" as each finishes: stopped after the first.
    const Interrupted stopped = interruptAtSecondRender(
        [&](const ProgressSink& progress) {
            ReciprocityInputs run = in;
            run.progress = progress;
            runReciprocity(run);
        },
        "batch", 1);
    // The flag raised after the first batch stops the second before it starts.
    expectKeptOne(stopped, "path_batch00");

    in.resume = true;
    const ReciprocityResult resumed = runReciprocity(in);
    ASSERT_EQ(uninterrupted.pairs.size(), resumed.pairs.size());
    for (std::size_t i = 0; i < resumed.pairs.size(); ++i) {
        const AgreementResult& a = uninterrupted.pairs[i].result;
        const AgreementResult& b = resumed.pairs[i].result;
        EXPECT_EQ(a.relativeDifference, b.relativeDifference);
        EXPECT_EQ(a.standardError, b.standardError);
        EXPECT_EQ(a.pixelsRejected, b.pixelsRejected);
        EXPECT_EQ(a.blocksRejected, b.blocksRejected);
        EXPECT_EQ(a.meanPValue, b.meanPValue);
    }
    EXPECT_EQ(uninterrupted.allAgree, resumed.allAgree);

    in.mode = render::RenderModeKind::Spectral;
    EXPECT_THAT(refusal([&] { runReciprocity(in); }),
                HasSubstr("path_batch00.exr: rendered with mode=rgb, this run asks for "
                          "mode=spectral"));
}

void expectSameAudit(const AuditedModel& a, const AuditedModel& b) {
    EXPECT_EQ(a.json, b.json);
    EXPECT_EQ(a.audit.alphas, b.audit.alphas);
    EXPECT_EQ(a.audit.cosines, b.audit.cosines);
    ASSERT_EQ(a.audit.cells.size(), b.audit.cells.size());
    for (std::size_t i = 0; i < a.audit.cells.size(); ++i) {
        const StabilityCell &x = a.audit.cells[i], &y = b.audit.cells[i];
        EXPECT_EQ(x.evaluations, y.evaluations);
        EXPECT_EQ(x.samples, y.samples);
        EXPECT_EQ(x.issues(), y.issues());
        EXPECT_EQ(x.negative, y.negative);
        EXPECT_EQ(x.worstFloatError, y.worstFloatError);
    }
    ASSERT_EQ(a.polarised.probes.size(), b.polarised.probes.size());
    for (std::size_t i = 0; i < a.polarised.probes.size(); ++i) {
        EXPECT_EQ(a.polarised.probes[i].what, b.polarised.probes[i].what);
        EXPECT_EQ(a.polarised.probes[i].cosTheta, b.polarised.probes[i].cosTheta);
        EXPECT_EQ(a.polarised.probes[i].jumpFloat, b.polarised.probes[i].jumpFloat);
        EXPECT_EQ(a.polarised.probes[i].jumpDouble, b.polarised.probes[i].jumpDouble);
    }
    EXPECT_EQ(a.polarised.evaluations, b.polarised.evaluations);
    EXPECT_EQ(a.polarised.worstJumpFloat, b.polarised.worstJumpFloat);
    EXPECT_EQ(a.polarised.discontinuities, b.polarised.discontinuities);
}

void expectSameStability(const StabilityResult& a, const StabilityResult& b) {
    ASSERT_EQ(a.models.size(), b.models.size());
    for (std::size_t m = 0; m < a.models.size(); ++m)
        expectSameAudit(a.models[m], b.models[m]);
    ASSERT_EQ(a.scenes.size(), b.scenes.size());
    for (std::size_t s = 0; s < a.scenes.size(); ++s) {
        EXPECT_EQ(a.scenes[s].rejectedSamples, b.scenes[s].rejectedSamples);
        EXPECT_EQ(a.scenes[s].largestSample, b.scenes[s].largestSample);
        EXPECT_EQ(a.scenes[s].meanLuminance, b.scenes[s].meanLuminance);
    }
}

// Interrupted after its first audit, and again after its first scene render: each resume takes
// back what was kept (an audit to the last bit, a render as a shard with its rejected-sample
// count) and reports what an uninterrupted run reports.
TEST_F(ExperimentResume, StabilityResumesFromItsKeptAuditsAndRendersWithTheSameNumbers) {
    StabilityInputs in;
    in.materials = {R"({"type":"dielectric","ior":1.5})",
                    R"({"type":"conductor","eta":0.5,"k":20})"};
    in.samples = 16;
    in.scenes = {lamina::testing::sourceFile("scenes/stress/tiny-bright-light.json").string(),
                 lamina::testing::sourceFile("scenes/stress/grazing-view.json").string()};
    in.spp = 2;
    in.overrides.resolution = {16, 12};
    in.keepDirectory = whole();
    const StabilityResult uninterrupted = runStability(in);
    EXPECT_EQ(uninterrupted.scenes.size(), 2u);

    in.keepDirectory = interrupted();
    const Interrupted afterAudit = interruptAtSecondRender(
        [&](const ProgressSink& progress) {
            StabilityInputs run = in;
            run.progress = progress;
            runStability(run);
        },
        "audited ", 1);
    const std::filesystem::path audit = interrupted() / "renders" / "model01_audit.json";
    EXPECT_EQ(afterAudit.kept, audit.string() +
                                   " (the same command with --resume continues from them without "
                                   "auditing them again)");
    ASSERT_TRUE(afterAudit.partial.has_value());
    const auto& dict = std::get<Data::Dict>(afterAudit.partial->value());
    ASSERT_EQ(dict.size(), 2u);  // renders (none yet) and models (one)
    EXPECT_EQ(std::get<std::string>(dict[1].key.value()), "models");
    EXPECT_EQ(std::get<Data::List>(dict[1].value.value()).size(), 1u);

    in.resume = true;
    const Interrupted afterRender = interruptAtSecondRender([&](const ProgressSink& progress) {
        StabilityInputs run = in;
        run.progress = progress;
        runStability(run);
    });
    EXPECT_THAT(afterRender.kept, HasSubstr("model02_audit.json, "));
    EXPECT_THAT(afterRender.kept, HasSubstr("scene01_tiny-bright-light.exr (the same command"));

    std::string log;
    in.progress = [&](const std::string& text) { log += text; };
    const StabilityResult resumed = runStability(in);
    EXPECT_THAT(log, HasSubstr(": kept from renders/model01_audit.json"));
    EXPECT_THAT(log, HasSubstr(": kept from renders/model02_audit.json"));
    EXPECT_THAT(log, HasSubstr(": kept from renders/scene01_tiny-bright-light.exr"));
    EXPECT_THAT(log, HasSubstr("rendering " + in.scenes[1]));
    expectSameStability(uninterrupted, resumed);

    in.samples = 32;
    EXPECT_THAT(refusal([&] { runStability(in); }),
                HasSubstr("model01_audit.json: audited with samples=16, this run asks for "
                          "samples=32: resume with the same options"));
    in.samples = 16;
    std::swap(in.materials[0], in.materials[1]);
    EXPECT_THAT(refusal([&] { runStability(in); }),
                HasSubstr("model01_audit.json: audited {\"type\":\"dielectric\",\"ior\":1.5}, "
                          "this run asks for {\"type\":\"conductor\""));
}

// Another scene file: refused by its hash, before anything is rendered.
TEST_F(ExperimentResume, RendersOfAnotherSceneAreRefused) {
    PolarisationInputs in;
    in.scene = lamina::testing::sourceFile("scenes/polarisation/two-mirrors.json").string();
    in.spp = 2;
    in.keepDirectory = interrupted();
    runPolarisation(in);  // keeps its renders (the command line removes them after the report)
    in.resume = true;
    std::ifstream original(in.scene);
    const std::string scene{std::istreambuf_iterator<char>(original), {}};
    in.scene = write("other.json", scene + "\n").string();
    EXPECT_THAT(refusal([&] { runPolarisation(in); }),
                HasSubstr("polarised.exr: rendered with scene files of hash "));
}

}  // namespace
}  // namespace lamina::experiments
