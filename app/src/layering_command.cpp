// `lamina layering MATERIAL... -o DIR [--scene SCENE]`: coated materials (the random walk)
// against their analytic layered twins (experiments/layering.h).
#include <CLI/CLI.hpp>

#include "interruption.h"
#include "lamina/experiments/layering.h"
#include "option_parsing.h"

namespace lamina::app {

void registerLayeringCommand(CLI::App& app) {
    auto a = std::make_shared<experiments::LayeringInputs>();
    auto output = std::make_shared<std::string>();
    std::string builtIns;
    for (const auto& [name, json] : experiments::layeringMaterials())
        builtIns += (builtIns.empty() ? "" : ", ") + name;
    CLI::App* cmd = app.add_subcommand(
        "layering",
        "Coated materials (random walk) against their analytic layered twins (fresnel and "
        "albedo coupling): albedo, lobes, error maps with standard errors, CIEDE2000 of renders");
    cmd->add_option("materials", a->materials,
                    "Coated materials: JSON, @file.json or a built-in name (" + builtIns + ")")
        ->required();
    addOutputDirectoryOption(cmd, *output);
    cmd->add_option("--estimates", a->estimates,
                    "Independent walk estimates per eval point (each of the material's "
                    "`samples` walks)")
        ->check(CLI::Range(2, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--albedo-samples", a->albedoSamples, "sample() calls per albedo angle")
        ->check(CLI::Range(2, 1 << 26))
        ->capture_default_str();
    cmd->add_option("--seed", a->seed, "Seed of the estimates and the renders")
        ->capture_default_str();
    cmd->add_option("--scene", a->scene,
                    "A test-object scene with a material named \"sample\", rendered with the walk "
                    "and each twin in both modes (e.g. scenes/layering/test-object.json)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--spp", a->spp, "Samples per pixel of every --scene render")
        ->check(CLI::Range(1, 1 << 24));
    cmd->callback([a, output] {
        a->progress = experiments::printToStderr;
        experiments::Report report(*output);
        runInterruptible("layering", [&] {
            experiments::writeLayeringReport(experiments::runLayering(*a), report);
            report.finish();
        });
    });
}

}  // namespace lamina::app
