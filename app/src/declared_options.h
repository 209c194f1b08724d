// A declared command's options (experiments/command_declaration.h) on a CLI::App: each option
// the command line has, with the declaration's name, help, default and check (range, names,
// an existing file, the options it excludes or needs), bound to a slot of its own. values()
// gives what the command line set, checked by the declaration as Python's keywords are.
#pragma once

#include <CLI/CLI.hpp>

#include <deque>
#include <string>
#include <utility>

#include "lamina/experiments/command_declaration.h"

namespace lamina::app {

class DeclaredOptions {
  public:
    /// Adds to `cmd` every option of `command` that the command line has, bound to slots of
    /// this object: it must live while `cmd` parses (a shared_ptr the callback keeps).
    DeclaredOptions(CLI::App& cmd, const experiments::CommandDecl& command);
    DeclaredOptions(const DeclaredOptions&) = delete;
    DeclaredOptions& operator=(const DeclaredOptions&) = delete;

    /// The values the command line gave; CLI::ValidationError (a usage error, exit status 2)
    /// naming the option for one the declaration refuses.
    experiments::OptionValues values() const;

  private:
    struct Slot {
        const experiments::OptionDecl* decl = nullptr;
        CLI::Option* option = nullptr;
        bool flag = false;
        long long integer = 0;
        double number = 0;
        std::string text;
        std::vector<std::string> texts;
    };
    CLI::Option* option(const std::string& name) const;

    const experiments::CommandDecl& command_;
    std::deque<Slot> slots_;  // a deque: the slots stay where CLI11 binds them
};

/// The option as the command line names it in messages: "--max-depth", "scene".
std::string commandLineName(const experiments::OptionDecl& option);

/// Runs `work`, turning an experiments::OptionError into its option's usage error.
template <typename Work>
decltype(auto) reportingUsageErrors(Work&& work) {
    try {
        return std::forward<Work>(work)();
    } catch (const experiments::OptionError& e) {
        throw CLI::ValidationError(commandLineName(e.option()), e.what());
    }
}

}  // namespace lamina::app
