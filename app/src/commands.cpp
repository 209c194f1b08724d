#include "commands.h"

#include <CLI/CLI.hpp>

namespace lamina::app {

void registerRenderCommand(CLI::App& app);
void registerBsdfCommand(CLI::App& app);
void registerSpectrumCommand(CLI::App& app);
void registerInfoCommand(CLI::App& app);
void registerBenchCommand(CLI::App& app);
void registerCompareCommand(CLI::App& app);
void registerReciprocityCommand(CLI::App& app);
void registerConvergenceCommand(CLI::App& app);
void registerFresnelCommand(CLI::App& app);
void registerStabilityCommand(CLI::App& app);

// Every subcommand is registered here, in the order `lamina --help` lists them.
void registerCommands(CLI::App& app) {
    registerRenderCommand(app);
    registerBsdfCommand(app);
    registerInfoCommand(app);
    registerBenchCommand(app);
    registerCompareCommand(app);
    registerReciprocityCommand(app);
    registerConvergenceCommand(app);
    registerFresnelCommand(app);
    registerStabilityCommand(app);
    registerSpectrumCommand(app);
}

}  // namespace lamina::app
