// `lamina stability [MATERIAL...] -o DIR [--scenes SCENE...]`: BSDF models on extreme inputs in
// float and double, and firefly statistics of stiff scenes (experiments/stability.h).
#include <CLI/CLI.hpp>

#include "interruption.h"
#include "lamina/experiments/stability.h"
#include "option_parsing.h"

namespace lamina::app {

void registerStabilityCommand(CLI::App& app) {
    auto a = std::make_shared<experiments::StabilityInputs>();
    auto output = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "stability",
        "Extreme-input sweep of BSDF models in float and double (NaN, Inf, negative, energy "
        "gain, weight != eval/pdf, float error) and firefly statistics of stiff scenes");
    cmd->add_option("materials", a->materials,
                    "Materials as JSON (default: a conductor, dielectric, standard and diffuse "
                    "set); roughness is replaced by the sweep's alpha");
    addOutputDirectoryOption(cmd, *output);
    cmd->add_option("--scenes", a->scenes, "Stiff scenes to render (e.g. scenes/stress/*.json)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--spp", a->spp, "Samples per pixel of the scene renders")
        ->check(CLI::Range(1, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--samples", a->samples, "BSDF samples per (alpha, angle) cell")
        ->check(CLI::Range(16, 1 << 24))
        ->capture_default_str();
    cmd->callback([a, output] {
        a->progress = experiments::printToStderr;
        experiments::Report report(*output);
        runInterruptible("stability", [&] {
            experiments::writeStabilityReport(experiments::runStability(*a), report);
            report.finish();
        });
    });
}

}  // namespace lamina::app
