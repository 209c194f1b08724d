#include "lamina/cli/commands.h"

#include <CLI/CLI.hpp>

namespace lamina::cli {

void registerCommands(CLI::App& app) {
    (void)app;  // The subcommands are added below as the libraries provide them.
}

}  // namespace lamina::cli
