// `lamina reciprocity SCENE -o DIR`: do camera tracing, light tracing and BDPT converge to the
// same image, and is every BSDF reciprocal (experiments/reciprocity.h)? Exit status 2 if a pair
// disagrees.
#include <CLI/CLI.hpp>

#include "interruption.h"
#include "lamina/experiments/reciprocity.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct ReciprocityArgs {
    std::string scene;
    std::string output;
    std::string integrators = render::kIntegratorNames.list(",");
    std::string mode{render::kRenderModeNames.name(render::RenderModeKind::Rgb)};
    std::string reference;
    std::string ablate;
    int spp = 256;
    int batches = 16;
    long long seed = 0;
    double alpha = 0.01;
    int block = 8;
    RenderOverrides overrides;
};

experiments::ReciprocityInputs inputs(const ReciprocityArgs& a) {
    experiments::ReciprocityInputs in;
    in.scene = a.scene;
    in.integrators =
        parseNameList(render::kIntegratorNames, a.integrators, "integrator", "--integrators");
    in.mode = parseName(render::kRenderModeNames, a.mode, "mode", "--mode");
    in.spp = a.spp;
    in.batches = a.batches;
    in.seed = std::uint64_t(a.seed);
    in.test.alpha = a.alpha;
    in.test.blockSize = a.block;
    in.reference = a.reference;
    in.ablations = parseNameList(experiments::kAblationNames, a.ablate, "", "--ablate");
    a.overrides.applyTo(in.overrides);
    in.progress = experiments::printToStderr;
    return in;
}

}  // namespace

void registerReciprocityCommand(CLI::App& app) {
    auto a = std::make_shared<ReciprocityArgs>();
    CLI::App* cmd = app.add_subcommand(
        "reciprocity",
        "Test whether path, light and bdpt converge to the same image (per-pixel and blockwise "
        "t-tests) and whether every BSDF is reciprocal; exit status 2 if they disagree");
    cmd->add_option("scene", a->scene, "Scene file")->required()->check(CLI::ExistingFile);
    addOutputDirectoryOption(cmd, a->output, "Directory for the images and t-statistic maps");
    cmd->add_option("--integrators", a->integrators, "Comma-separated list")->capture_default_str();
    cmd->add_option("--spp", a->spp, "Samples per pixel per integrator (over all batches)")
        ->check(CLI::Range(2, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--batches", a->batches,
                    "Independent batches per integrator (the variance estimate's sample size)")
        ->check(CLI::Range(2, 4096))
        ->capture_default_str();
    cmd->add_option("--mode", a->mode, "Render mode")
        ->check(CLI::IsMember(render::kRenderModeNames.names()))
        ->capture_default_str();
    cmd->add_option("--reference", a->reference, "Also test each integrator against this EXR")
        ->check(CLI::ExistingFile);
    cmd->add_option("--alpha", a->alpha, "Significance level of each test")
        ->check(CLI::Range(1e-6, 0.5))
        ->capture_default_str();
    cmd->add_option("--block", a->block, "Block size of the blockwise test")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    addResolutionOption(cmd, a->overrides);
    addMaxDepthOption(cmd, a->overrides);
    cmd->add_option("--seed", a->seed, "Base seed")->check(CLI::Range(0LL, 2147483647LL));
    addThreadsOption(cmd, a->overrides);
    cmd->add_option("--ablate", a->ablate,
                    "Reproduce a known bug on purpose: adjoint-correction (drop the shading-normal "
                    "factor on light paths), transport-mode (radiance's 1/eta^2 on light paths), "
                    "swapped-directions (f(wi, wo) at light-path connections)");
    cmd->callback([a] {
        const experiments::ReciprocityInputs in = inputs(*a);
        experiments::Report report(a->output);
        bool agree = true;
        runInterruptible("reciprocity", [&] {
            const experiments::ReciprocityResult result = experiments::runReciprocity(in);
            experiments::writeReciprocityReport(result, report);
            agree = result.allAgree;
        });
        if (!agree) throw CLI::RuntimeError(2);
    });
}

}  // namespace lamina::app
