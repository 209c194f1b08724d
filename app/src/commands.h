// Every `lamina` subcommand is registered here, in one place. A command adds itself to the
// application (its options, help text and callback); a callback reports bad input by throwing
// lamina::InputError, which main() turns into one line on stderr and exit code 1.
#pragma once

namespace CLI {
class App;
}

namespace lamina::app {

/// Adds every subcommand to `app`.
void registerCommands(CLI::App& app);

}  // namespace lamina::app
