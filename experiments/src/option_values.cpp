#include "lamina/experiments/option_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "lamina/experiments/command_declaration.h"
#include "lamina/experiments/text_format.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

// The whole text as a finite number, or nothing.
std::optional<double> finiteNumber(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
    return v;
}

const char* expectedKind(OptionKind kind) {
    switch (kind) {
        case OptionKind::Flag:
            return "expected true or false";
        case OptionKind::Integer:
            return "expected an integer";
        case OptionKind::Number:
            return "expected a number";
        case OptionKind::Text:
        case OptionKind::File:
        case OptionKind::Name:
            return "expected a text";
        case OptionKind::NameList:
        case OptionKind::TextList:
        case OptionKind::NumberList:
            return "expected a list";
        case OptionKind::Resolution:
            return "expected a resolution";
        case OptionKind::Callback:
            return "expected a callable";
    }
    return "expected a value";
}

[[noreturn]] void refuse(const OptionDecl& o) {
    throw OptionError(o, expectedKind(o.kind));
}

void checkNumber(const OptionDecl& o, double v) {
    if (o.positiveUnit) {
        if (!(v > 0) || !std::isfinite(v))
            throw OptionError(o, "expected a positive number" +
                                     (o.positiveUnit->empty() ? "" : " of " + *o.positiveUnit) +
                                     ", got " + formatText("%.17g", v));
        return;
    }
    if (!std::isfinite(v)) throw OptionError(o, "expected a finite number");
    if (o.numberRange && (v < o.numberRange->first || v > o.numberRange->second))
        throw OptionError(o, formatText("expected a number in [%.17g, %.17g], got %.17g",
                                        o.numberRange->first, o.numberRange->second, v));
}

// The value of `o` in its canonical form (a Number given as an integer becomes a double), or
// OptionError.
OptionValue checked(const OptionDecl& o, OptionValue value) {
    if (o.kind == OptionKind::Number)
        if (const auto* i = std::get_if<long long>(&value)) value = double(*i);
    switch (o.kind) {
        case OptionKind::Flag:
            if (!std::holds_alternative<bool>(value)) refuse(o);
            break;
        case OptionKind::Integer: {
            const auto* v = std::get_if<long long>(&value);
            if (!v) refuse(o);
            if (*v < o.minInteger || *v > o.maxInteger)
                throw OptionError(o, "expected an integer in [" + std::to_string(o.minInteger) +
                                         ", " + std::to_string(o.maxInteger) + "], got " +
                                         std::to_string(*v));
            break;
        }
        case OptionKind::Number: {
            const auto* v = std::get_if<double>(&value);
            if (!v) refuse(o);
            checkNumber(o, *v);
            break;
        }
        case OptionKind::Text:
        case OptionKind::File:
            if (!std::holds_alternative<std::string>(value)) refuse(o);
            break;
        case OptionKind::Name: {
            const auto* v = std::get_if<std::string>(&value);
            if (!v) refuse(o);
            if (std::find(o.names.begin(), o.names.end(), *v) == o.names.end())
                throw OptionError(o, "expected one of " + joined(o.names) + ", got " + quoted(*v));
            break;
        }
        case OptionKind::NameList:
        case OptionKind::TextList:
        case OptionKind::NumberList: {
            const auto* list = std::get_if<std::vector<std::string>>(&value);
            if (!list) refuse(o);
            for (const std::string& item : *list) {
                if (o.kind == OptionKind::NameList &&
                    std::find(o.names.begin(), o.names.end(), item) == o.names.end())
                    throw OptionError(o, "unknown " + (o.what.empty() ? "" : o.what + " ") +
                                             quoted(item) + "; expected " + joined(o.names));
                if (o.kind == OptionKind::NumberList && !finiteNumber(item))
                    throw OptionError(o, "expected numbers, got " + quoted(item));
            }
            break;
        }
        case OptionKind::Resolution: {
            const auto* r = std::get_if<std::pair<int, int>>(&value);
            const int max = render::kMaxResolutionOverride;
            if (!r || r->first < 1 || r->second < 1 || r->first > max || r->second > max)
                throw OptionError(o, "expected WIDTHxHEIGHT, each in [1, " + std::to_string(max) +
                                         "], e.g. 512x512");
            break;
        }
        case OptionKind::Callback:
            refuse(o);  // a front end keeps its callables itself
    }
    return value;
}

}  // namespace

std::vector<std::string> splitList(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

void OptionValues::set(std::string_view name, OptionValue value) {
    const OptionDecl& o = command_->option(name);
    given_[o.name] = checked(o, std::move(value));
}

void OptionValues::setText(std::string_view name, const std::string& text) {
    const OptionDecl& o = command_->option(name);
    switch (o.kind) {
        case OptionKind::Flag:
            if (text != "true" && text != "false") refuse(o);
            return set(name, text == "true");
        case OptionKind::Integer: {
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0' || errno == ERANGE)
                throw OptionError(o, "expected an integer, got " + quoted(text));
            return set(name, v);
        }
        case OptionKind::Number: {
            const auto v = finiteNumber(text);
            if (!v) throw OptionError(o, "expected a finite number, got " + quoted(text));
            return set(name, *v);
        }
        case OptionKind::NameList:
        case OptionKind::NumberList:
            return set(name, splitList(text));
        case OptionKind::TextList:
            return set(name, std::vector<std::string>{text});
        case OptionKind::Resolution: {
            const auto r = render::parseResolutionText(text);
            if (!r) return set(name, std::pair{0, 0});  // refused with the option's message
            return set(name, *r);
        }
        default:
            return set(name, text);
    }
}

void OptionValues::finish() const {
    for (const OptionDecl& o : command_->options) {
        if (!given(o.name)) continue;
        // The command line checks these while parsing (CLI11's excludes and needs); a front
        // end that does not, Python, meets them here, and its spelling names the other option.
        for (const std::string& other : o.excludes)
            if (given(other))
                throw OptionError(o, "excludes " + command_->option(other).python + " (as --" +
                                         o.name + " excludes --" + other + ")");
        for (const std::string& other : o.needs)
            if (!given(other)) throw OptionError(o, "needs " + command_->option(other).python);
    }
}

bool OptionValues::given(std::string_view name) const {
    command_->option(name);  // a name the declaration lacks is a bug
    return given_.find(name) != given_.end();
}

const OptionValue& OptionValues::value(std::string_view name) const {
    const OptionDecl& o = command_->option(name);
    const auto it = given_.find(name);
    return it != given_.end() ? it->second : o.defaultValue;
}

bool OptionValues::flag(std::string_view name) const {
    const auto* v = std::get_if<bool>(&value(name));
    return v && *v;
}

std::optional<long long> OptionValues::integer(std::string_view name) const {
    if (const auto* v = std::get_if<long long>(&value(name))) return *v;
    return std::nullopt;
}

std::optional<double> OptionValues::number(std::string_view name) const {
    if (const auto* v = std::get_if<double>(&value(name))) return *v;
    return std::nullopt;
}

std::optional<std::string> OptionValues::text(std::string_view name) const {
    if (const auto* v = std::get_if<std::string>(&value(name))) return *v;
    return std::nullopt;
}

std::vector<std::string> OptionValues::texts(std::string_view name) const {
    if (const auto* v = std::get_if<std::vector<std::string>>(&value(name))) return *v;
    return {};
}

std::optional<std::pair<int, int>> OptionValues::resolution(std::string_view name) const {
    if (const auto* v = std::get_if<std::pair<int, int>>(&value(name))) return *v;
    return std::nullopt;
}

}  // namespace lamina::experiments
