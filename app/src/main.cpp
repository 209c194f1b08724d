// The `lamina` command: subcommands, help, and one error policy for all of them:
// exit 0 on success, 2 on a usage error, 1 on any other error, with exactly one line on stderr
// that starts with "lamina: error: " (control characters in it escaped, whatever the text
// echoes).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include "commands.h"
#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/core/printable.h"
#include "lamina/version.h"

namespace {

int fail(const std::string& message, int status) {
    std::cerr << "lamina: error: " << lamina::escapeControl(message) << "\n";
    return status;
}

// A filesystem error as the others read: the path first, then what went wrong (not the
// library's "filesystem error: cannot ...: Reason [path]").
std::string describe(const std::filesystem::filesystem_error& e) {
    const std::string what = e.code().message();
    if (e.path1().empty()) return what;
    return e.path1().string() + ": " + what;
}

}  // namespace

int main(int argc, char** argv) {
    lamina::app::installSignalCleanup();
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
        return fail(std::string(e.what()) + " (run `lamina --help` for usage)", 2);
    } catch (const lamina::InputError& e) {
        return fail(e.what(), 1);
    } catch (const std::filesystem::filesystem_error& e) {
        return fail(describe(e), 1);
    } catch (const std::bad_alloc&) {
        return fail("out of memory (a smaller --resolution, or fewer --aovs, may fit)", 1);
    } catch (const std::exception& e) {
        return fail(e.what(), 1);
    }
    return 0;
}
