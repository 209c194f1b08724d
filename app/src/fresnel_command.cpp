// `lamina fresnel MATERIAL... -o DIR`: how far RGB mode's Fresnel models are from the exact
// spectral Fresnel reflectance (experiments/fresnel.h).
#include <CLI/CLI.hpp>

#include "interruption.h"
#include "lamina/experiments/fresnel.h"
#include "option_parsing.h"

namespace lamina::app {

void registerFresnelCommand(CLI::App& app) {
    auto a = std::make_shared<experiments::FresnelInputs>();
    auto output = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "fresnel",
        "Exact spectral Fresnel against the RGB models (Schlick, shadowed F90, F82, spherical "
        "Gaussian): errors, CIEDE2000, curves, swatches; optionally a scene in both modes");
    cmd->add_option("materials", a->materials,
                    "Metals (Au, Ag, Cu, Al, ...), glasses (bk7, diamond, ...) or n/k files")
        ->required();
    addOutputDirectoryOption(cmd, *output);
    cmd->add_option("--scene", a->scene, "Also render this scene in both modes and compare")
        ->check(CLI::ExistingFile);
    cmd->add_option("--spp", a->spp, "Samples per pixel of the --scene renders")
        ->check(CLI::Range(1, 1 << 24));
    cmd->callback([a, output] {
        a->progress = experiments::printToStderr;
        experiments::Report report(*output);
        runInterruptible("fresnel", [&] {
            experiments::writeFresnelReport(experiments::runFresnel(*a), report);
            report.finish();
        });
    });
}

}  // namespace lamina::app
