#include "commands.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>

namespace lamina::app {

namespace {

// strtod, which CLI11 converts floating options with, accepts "nan", "inf" and overflowing
// literals such as 1e999; none of them is a meaningful time, exposure or scale. A token that
// is not a number at all is left to CLI11's own conversion error.
std::string refuseNonFinite(std::string& token) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || std::isfinite(value)) return {};
    return "expected a finite number, got " + token;
}

// Every floating option of every command (CLI11 names their type FLOAT) gets the check, so a
// new option cannot forget it.
void requireFiniteFloats(CLI::App& app) {
    for (CLI::Option* option : app.get_options())
        if (option->get_type_name().find("FLOAT") != std::string::npos)
            option->check(CLI::Validator(refuseNonFinite, "FINITE"));
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        requireFiniteFloats(*sub);
}

}  // namespace

void registerRenderCommand(CLI::App& app);
void registerMergeCommand(CLI::App& app);
void registerFarmCommand(CLI::App& app);
void registerBsdfCommand(CLI::App& app);
void registerSpectrumCommand(CLI::App& app);
void registerInfoCommand(CLI::App& app);
void registerConvertCommand(CLI::App& app);
void registerBenchCommand(CLI::App& app);
void registerCompareCommand(CLI::App& app);
void registerExperimentCommands(CLI::App& app);  // every experiment of experiments/

// Every subcommand is registered here, in the order `lamina --help` lists them.
void registerCommands(CLI::App& app) {
    registerRenderCommand(app);
    registerMergeCommand(app);
    registerFarmCommand(app);
    registerBsdfCommand(app);
    registerInfoCommand(app);
    registerConvertCommand(app);
    registerBenchCommand(app);
    registerCompareCommand(app);
    registerExperimentCommands(app);
    registerSpectrumCommand(app);
    requireFiniteFloats(app);
}

}  // namespace lamina::app
