// `lamina reciprocity|convergence|fresnel|stability|layering SCENE-OR-MATERIALS -o DIR`: every
// experiment declared in experiments/ (command_declaration.h) is a command here, with no file
// of its own: its options come from the declaration, its inputs and report from the
// experiment's `report`. The report goes into --output's directory; a signal during the
// computation writes no report (runInterruptible).
#include <CLI/CLI.hpp>

#include <memory>

#include "declared_options.h"
#include "interruption.h"
#include "lamina/experiments/command_declaration.h"
#include "lamina/version.h"

namespace lamina::app {

void registerExperimentCommands(CLI::App& app) {
    for (const experiments::CommandDecl& command : experiments::commandDeclarations()) {
        if (!command.isExperiment()) continue;
        CLI::App* cmd = app.add_subcommand(command.name, command.help);
        auto options = std::make_shared<DeclaredOptions>(*cmd, command);
        cmd->callback([options, &command] {
            const experiments::OptionValues values = options->values();
            const experiments::CommandContext context{{LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT},
                                                      experiments::printToStderr};
            const experiments::ReportWork work =
                reportingUsageErrors([&] { return command.report(values, context); });
            experiments::Report report(*values.text("output"));
            int status = 0;
            const auto run = [&] { status = work.run(report); };
            if (work.interruptible)
                runInterruptible(command.name, run);
            else
                run();
            if (status != 0) throw CLI::RuntimeError(status);
        });
    }
}

}  // namespace lamina::app
