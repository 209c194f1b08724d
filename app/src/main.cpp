// The `lamina` command: subcommands, help, and one error policy for all of them:
// exit 0 on success, 2 on a usage error, 1 on any other error, with one clear line on stderr.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.h"
#include "lamina/core/error.h"
#include "lamina/version.h"

int main(int argc, char** argv) {
    CLI::App app{"lamina " LAMINA_VERSION_STRING
                 " - an offline renderer for comparing material and light-transport models",
                 "lamina"};
    app.set_version_flag("--version", "lamina " LAMINA_VERSION_STRING);
    app.require_subcommand(1);
    app.fallthrough(false);
    app.footer("Run `lamina COMMAND --help` for the options of a command.");
    lamina::app::registerCommands(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a command's own verdict (e.g. reciprocity: 2)
    } catch (const CLI::ParseError& e) {
        std::cerr << "lamina: error: " << e.what() << "\n"
                  << "Run `lamina --help` for usage.\n";
        return 2;
    } catch (const lamina::InputError& e) {
        std::cerr << "lamina: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "lamina: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
