// `lamina convergence SCENE -o DIR`: error against render time for every combination of
// integrator and render mode (experiments/convergence.h).
#include <CLI/CLI.hpp>

#include "interruption.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/merged_convergence.h"
#include "lamina/version.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct ConvergenceArgs {
    std::string scene;
    std::string output;
    std::string reference;
    std::string integrators = render::kIntegratorNames.list(",");
    std::string modes{render::kRenderModeNames.name(render::RenderModeKind::Rgb)};
    std::string levels = "1e-2,1e-3";
    std::string sampler;
    std::string referenceIntegrator{render::kIntegratorNames.name(render::IntegratorKind::Path)};
    double seconds = 10;
    double referenceSeconds = 0;
    bool allowCorrelatedReference = false;
    RenderOverrides overrides;
    std::string merged;
};

std::vector<experiments::ErrorLevel> parseLevels(const std::string& list) {
    std::vector<experiments::ErrorLevel> levels;
    for (const std::string& l : splitList(list)) {
        try {
            levels.push_back({std::stod(l), l});
        } catch (const std::exception&) {
            throw CLI::ValidationError("--levels", "expected numbers, got \"" + l + "\"");
        }
    }
    return levels;
}

experiments::ConvergenceInputs inputs(const ConvergenceArgs& a) {
    experiments::ConvergenceInputs in;
    in.scene = a.scene;
    in.reference = a.reference;
    in.allowCorrelatedReference = a.allowCorrelatedReference;
    in.build = {LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT};
    in.levels = parseLevels(a.levels);
    in.integrators =
        parseNameList(render::kIntegratorNames, a.integrators, "integrator", "--integrators");
    in.modes = parseNameList(render::kRenderModeNames, a.modes, "mode", "--modes");
    in.referenceIntegrator = parseName(render::kIntegratorNames, a.referenceIntegrator,
                                       "integrator", "--reference-integrator");
    in.seconds = a.seconds;
    in.referenceSeconds = a.referenceSeconds;
    if (!a.sampler.empty())
        in.overrides.sampler = parseName(render::kSamplerNames, a.sampler, "sampler", "--sampler");
    a.overrides.applyTo(in.overrides);
    in.progress = experiments::printToStderr;
    return in;
}

}  // namespace

void registerConvergenceCommand(CLI::App& app) {
    auto a = std::make_shared<ConvergenceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convergence",
        "Error against render time for each integrator and mode: CSV, log-log plot, fitted "
        "slopes, time to reach error levels, a Markdown summary");
    cmd->add_option("scene", a->scene, "Scene file")->required()->check(CLI::ExistingFile);
    addOutputDirectoryOption(cmd, a->output);
    cmd->add_option("--reference", a->reference,
                    "Reference EXR (default: rendered first, per mode, with the path integrator)")
        ->check(CLI::ExistingFile);
    cmd->add_flag("--allow-correlated-reference", a->allowCorrelatedReference,
                  "Accept a --reference rendered with the measured renders' sampler and seed "
                  "(their errors are then understated)");
    cmd->add_option("--integrators", a->integrators, "Comma-separated list")->capture_default_str();
    cmd->add_option("--modes", a->modes,
                    "Comma-separated list of " + render::kRenderModeNames.list())
        ->capture_default_str();
    cmd->add_option("--time", a->seconds, "Render time of each combination, seconds")
        ->check(positiveNumber("seconds"))
        ->capture_default_str();
    cmd->add_option("--reference-time", a->referenceSeconds,
                    "Render time of each rendered reference (default: 20 x --time)")
        ->check(positiveNumber("seconds"));
    cmd->add_option("--reference-integrator", a->referenceIntegrator,
                    "Integrator of the rendered references (bdpt for caustics)")
        ->check(CLI::IsMember(render::kIntegratorNames.names()))
        ->capture_default_str();
    cmd->add_option("--levels", a->levels, "relMSE levels for the time-to-error columns")
        ->capture_default_str();
    addResolutionOption(cmd, a->overrides);
    cmd->add_option("--sampler", a->sampler,
                    "Sample generator of the measured renders (the reference always uses Sobol)")
        ->check(CLI::IsMember(render::kSamplerNames.names()));
    addMaxDepthOption(cmd, a->overrides);
    addThreadsOption(cmd, a->overrides);
    cmd->add_option("--merged", a->merged,
                    "Comma-separated images of `lamina merge`: measure them against "
                    "--reference instead of rendering (merged.csv)");
    cmd->callback([a] {
        if (!a->merged.empty()) {
            if (a->reference.empty()) throw CLI::ValidationError("--merged", "needs --reference");
            experiments::MergedSetInputs in{a->scene, {}, a->reference};
            for (const std::string& image : splitList(a->merged))
                in.images.emplace_back(image);
            experiments::Report report(a->output);
            experiments::writeMergedSetReport(experiments::measureMergedSets(in), report);
            report.finish();
            return;
        }
        const experiments::ConvergenceInputs in = inputs(*a);
        experiments::Report report(a->output);
        runInterruptible("convergence", [&] {
            experiments::writeConvergenceReport(experiments::runConvergence(in), report);
            report.finish();
        });
    });
}

}  // namespace lamina::app
