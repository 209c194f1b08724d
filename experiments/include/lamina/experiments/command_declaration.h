// The commands that both front ends have (`lamina render|compare|reciprocity|convergence|
// fresnel|stability|layering|polarisation|media` and the Python functions of the same names), each
// declared once: its name and help, and per option its name, kind, default, range or names, help
// text, and where the front ends differ, with the reason. The command line adds its options from
// these (app/src/declared_options.h), the Python module takes its keywords and defaults from them
// (python/src/experiments_binding.cpp), and tests/python/test_front_ends.py fails when either
// front end has an option the declaration does not list for it.
//
// An experiment's declaration also says how it runs: `report` for the command line (the inputs
// read from the options, then the report written), `data` for Python (the result as Data). A new
// experiment is its files in experiments/ and one declaration (experiments/src/
// NAME_declaration.cpp, listed in command_declaration.cpp); both front ends pick it up.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/experiments/option_values.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/experiments/result_data.h"
#include "lamina/output/render_metadata.h"

namespace lamina::experiments {

enum class OptionKind {
    Flag,        ///< on or off (Python: a bool)
    Integer,     ///< in [minInteger, maxInteger]
    Number,      ///< finite; in numberRange if any, or above zero (positiveUnit)
    Text,        ///< any text
    File,        ///< a file name (Python: also an os.PathLike)
    Name,        ///< one of `names`
    NameList,    ///< names among `names` (command line: comma-separated; Python: a list)
    TextList,    ///< several texts (command line: several arguments; Python: a list, or one str)
    NumberList,  ///< numbers, kept as written (command line: comma-separated; Python: a list)
    Resolution,  ///< WIDTHxHEIGHT (Python: also (width, height))
    Callback,    ///< a callable (Python only)
};
inline constexpr NameTable kOptionKindNames{std::array{
    NameEntry{OptionKind::Flag, "flag"}, NameEntry{OptionKind::Integer, "integer"},
    NameEntry{OptionKind::Number, "number"}, NameEntry{OptionKind::Text, "text"},
    NameEntry{OptionKind::File, "file"}, NameEntry{OptionKind::Name, "name"},
    NameEntry{OptionKind::NameList, "names"}, NameEntry{OptionKind::TextList, "texts"},
    NameEntry{OptionKind::NumberList, "numbers"}, NameEntry{OptionKind::Resolution, "resolution"},
    NameEntry{OptionKind::Callback, "callback"}}};

/// Which front ends have an option.
enum class FrontEnd { Both, CommandLine, Python };
inline constexpr NameTable kFrontEndNames{
    std::array{NameEntry{FrontEnd::Both, "both"}, NameEntry{FrontEnd::CommandLine, "command line"},
               NameEntry{FrontEnd::Python, "python"}}};

/// "max-depth" -> "max_depth": an option's Python spelling unless declared otherwise.
std::string pythonSpelling(std::string_view name);

struct OptionDecl {
    std::string name;  ///< the command line's spelling without dashes ("max-depth")
    OptionKind kind = OptionKind::Text;
    std::string help;
    char shortName = 0;  ///< -o for --output; 0: none
    bool positional = false;
    bool required = false;
    OptionValue defaultValue;  ///< nothing: unset (the scene's setting, or none)
    long long minInteger = 0, maxInteger = 0;
    std::optional<std::pair<double, double>> numberRange;
    std::optional<std::string> positiveUnit;   ///< a Number above zero ("seconds", or "")
    std::vector<std::string> names;            ///< of Name and NameList, from a NameTable
    std::string what;                          ///< NameList's messages: "integrator"
    bool mustExist = false;                    ///< a File the command line checks first
    std::vector<std::string> excludes, needs;  ///< other options, by name
    FrontEnd frontEnd = FrontEnd::Both;
    std::string python;  ///< the Python spelling
    /// Why the option is on one front end only, or spelled or given differently in Python.
    std::string difference;

    bool onCommandLine() const { return frontEnd != FrontEnd::Python; }
    bool onPython() const { return frontEnd != FrontEnd::CommandLine; }
    /// The command line's spelling: "--max-depth", "-o,--output", or a positional's name.
    std::string commandLineNames() const;

    OptionDecl& byDefault(OptionValue value);
    OptionDecl& shortFlag(char c);
    OptionDecl& asPositional();
    OptionDecl& asRequired();
    OptionDecl& existing();
    OptionDecl& excluding(std::string other);
    OptionDecl& needing(std::string other);
    OptionDecl& commandLineOnly(std::string reason);
    OptionDecl& pythonOnly(std::string reason);
    /// Spelled `spelling` in Python.
    OptionDecl& spelledInPython(std::string spelling, std::string reason);
    /// The same name in Python, given or answered differently.
    OptionDecl& differsInPython(std::string reason);
};

OptionDecl flagOption(std::string name, std::string help);
OptionDecl integerOption(std::string name, std::string help, long long min, long long max);
/// A finite number, in [min, max] if given.
OptionDecl numberOption(std::string name, std::string help);
OptionDecl numberOption(std::string name, std::string help, double min, double max);
/// A finite number above zero; `unit` names it in the message ("seconds").
OptionDecl positiveOption(std::string name, std::string help, std::string unit = "");
OptionDecl textOption(std::string name, std::string help);
OptionDecl fileOption(std::string name, std::string help);
OptionDecl textListOption(std::string name, std::string help);
OptionDecl numberListOption(std::string name, std::string help);
OptionDecl resolutionOption(std::string name, std::string help);
OptionDecl callbackOption(std::string name, std::string help);
OptionDecl nameOption(std::string name, std::string help, std::vector<std::string> names);
OptionDecl nameListOption(std::string name, std::string help, std::vector<std::string> names,
                          std::string what);
template <typename E, std::size_t N>
OptionDecl nameOption(std::string name, std::string help, const NameTable<E, N>& table) {
    return nameOption(std::move(name), std::move(help), table.names());
}
template <typename E, std::size_t N>
OptionDecl nameListOption(std::string name, std::string help, const NameTable<E, N>& table,
                          std::string what) {
    return nameListOption(std::move(name), std::move(help), table.names(), std::move(what));
}
/// The names of `values` in `table` (an Inputs struct's default list as a default value).
template <typename E, std::size_t N>
std::vector<std::string> namesOf(const NameTable<E, N>& table, const std::vector<E>& values) {
    std::vector<std::string> out;
    for (const E v : values)
        out.emplace_back(table.name(v));
    return out;
}

/// What a front end hands a command besides its options.
struct CommandContext {
    render::BuildInfo build;  ///< stamped into the images an experiment writes
    ProgressSink progress;    ///< the command line's stderr; Python's: none
};

/// An experiment's work on the command line: compute, write the report, return the exit
/// status (0, or the command's verdict: reciprocity's 2). `interruptible`: it renders, so the
/// first SIGINT stops the render in flight instead of the process.
struct ReportWork {
    std::function<int(Report& report)> run;
    bool interruptible = true;
};

struct CommandDecl {
    std::string name;
    std::string help;
    std::string returns;  ///< what the Python function returns (its docstring)
    std::vector<OptionDecl> options;
    /// An experiment on the command line: reads its inputs from the options (OptionError) and
    /// returns the work, whose report goes into the directory of the option `output`. Empty
    /// for a command with a front end of its own (render, compare).
    std::function<ReportWork(const OptionValues&, const CommandContext&)> report;
    /// The experiment in Python: run, the result as data. Empty as `report`.
    std::function<Data(const OptionValues&, const CommandContext&)> data;

    bool isExperiment() const { return bool(report); }
    const OptionDecl* find(std::string_view optionName) const;
    /// std::logic_error for a name the declaration lacks (a bug, not bad input).
    const OptionDecl& option(std::string_view optionName) const;
};

/// Every declared command: render, compare, then the experiments in the order `lamina --help`
/// lists them.
const std::vector<CommandDecl>& commandDeclarations();
/// std::logic_error for a command not declared.
const CommandDecl& commandDeclaration(std::string_view name);

}  // namespace lamina::experiments
