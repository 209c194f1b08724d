// The values a command's options were given, by either front end (the command line or
// Python), checked against the command's declaration (command_declaration.h). The experiments'
// inputs and the render options are read from these once, for both front ends, so the two
// cannot read an option differently.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "lamina/core/name_table.h"

namespace lamina::experiments {

struct OptionDecl;
struct CommandDecl;

/// One option's value: a flag, an integer, a number, a text (a name, a file), texts (names,
/// files, numbers as written) or a resolution (width, height).
using OptionValue = std::variant<std::monostate, bool, long long, double, std::string,
                                 std::vector<std::string>, std::pair<int, int>>;

/// A value the declaration refuses. Each front end names the option in its own spelling:
/// `--max-depth: ...` on the command line (a usage error, exit status 2), `max_depth: ...` in
/// Python (ValueError).
class OptionError : public std::runtime_error {
  public:
    OptionError(const OptionDecl& option, const std::string& message)
        : std::runtime_error(message), option_(&option) {}
    const OptionDecl& option() const { return *option_; }

  private:
    const OptionDecl* option_;
};

/// "a,b,,c" -> a, b, c: a list as the command line writes it.
std::vector<std::string> splitList(const std::string& list);

class OptionValues {
  public:
    explicit OptionValues(const CommandDecl& command) : command_(&command) {}
    const CommandDecl& command() const { return *command_; }

    /// Sets a value given: OptionError if it is not of the option's kind, lies outside its
    /// range or is not among its names.
    void set(std::string_view name, OptionValue value);
    /// Sets a value written as the command line writes it ("512x512", "path,bdpt",
    /// "1e-2,1e-3", "12"), then as set().
    void setText(std::string_view name, const std::string& text);
    /// Once every value is set: OptionError for an option given with one it excludes or
    /// without one it needs. (A required option is each front end's to demand: CLI11's
    /// required(), a Python function's signature; render's scene comes to Python apart from
    /// its keywords.)
    void finish() const;

    /// Whether the option was given (its default does not count).
    bool given(std::string_view name) const;
    /// The value given, else the declared default, else nothing.
    bool flag(std::string_view name) const;
    std::optional<long long> integer(std::string_view name) const;
    std::optional<double> number(std::string_view name) const;
    std::optional<std::string> text(std::string_view name) const;
    /// A list (texts, names, numbers as written); empty when neither given nor declared.
    std::vector<std::string> texts(std::string_view name) const;
    std::optional<std::pair<int, int>> resolution(std::string_view name) const;

    /// A name option as its value in `table`.
    template <typename E, std::size_t N>
    std::optional<E> choice(const NameTable<E, N>& table, std::string_view name) const {
        if (const auto t = text(name)) return table.find(*t);
        return std::nullopt;
    }
    /// A list of names as their values in `table`.
    template <typename E, std::size_t N>
    std::vector<E> choices(const NameTable<E, N>& table, std::string_view name) const {
        std::vector<E> out;
        for (const std::string& t : texts(name))
            if (const auto e = table.find(t)) out.push_back(*e);
        return out;
    }

  private:
    const OptionValue& value(std::string_view name) const;

    const CommandDecl* command_;
    std::map<std::string, OptionValue, std::less<>> given_;
};

}  // namespace lamina::experiments
