// Option values of the commands that are not declared in experiments/ (command_declaration.h)
// or that the command line alone has: comma-separated lists, names looked up in an
// enumeration's table, positive numbers, image sizes, sample ranges and crops. Errors are
// CLI::ValidationError naming the option (exit status 2).
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/render/render_limits.h"
#include "lamina/render/renderer.h"

namespace lamina::app {

inline std::vector<std::string> splitList(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

/// The value called `name` in `table`; `what` names the kind in the message ("integrator"),
/// if the option's name does not say it.
template <typename E, std::size_t N>
E parseName(const NameTable<E, N>& table, const std::string& name, const std::string& what,
            const std::string& option) {
    if (const auto value = table.find(name)) return *value;
    throw CLI::ValidationError(option, "unknown " + (what.empty() ? "" : what + " ") + "\"" + name +
                                           "\"; expected " + table.list());
}

/// A finite number above zero, with a message that says so (CLI::PositiveNumber's names
/// the largest double, 309 digits). `what` names the quantity: "seconds" (or nothing).
inline CLI::Validator positiveNumber(const std::string& what) {
    return CLI::Validator(
        [what](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(v) || !(v > 0))
                return "expected a positive number" + (what.empty() ? "" : " of " + what) +
                       ", got \"" + text + "\"";
            return {};
        },
        "POSITIVE");
}

/// "WIDTHxHEIGHT", each in [1, 65536] as the scene's film.resolution (render_limits.h).
inline std::pair<int, int> parseResolution(const std::string& text) {
    if (const auto r = render::parseResolutionText(text)) return *r;
    throw CLI::ValidationError("--resolution",
                               "expected WIDTHxHEIGHT, each in [1, 65536], e.g. 512x512");
}

/// "FIRST:COUNT" (`render --samples`): sample indices [FIRST, FIRST + COUNT).
inline render::SampleRange parseSampleRange(const std::string& text) {
    long long first = -1, count = 0;
    char colon = 0;
    std::istringstream in(text);
    if (!(in >> first >> colon >> count) || colon != ':' || !in.eof() || first < 0 || count < 1 ||
        first + count > 2147483647LL)
        throw CLI::ValidationError("--samples",
                                   "expected FIRST:COUNT with FIRST >= 0, COUNT >= 1 "
                                   "and FIRST + COUNT < 2^31, e.g. 0:64, got \"" +
                                       text + "\"");
    return {int(first), int(count)};
}

/// "X0,X1,Y0,Y1" (`render --crop`): half-open pixel bounds (checked against the film when the
/// render starts).
inline render::PixelBounds parsePixelBounds(const std::string& text) {
    const std::vector<std::string> parts = splitList(text);
    render::PixelBounds b;
    int* fields[4] = {&b.x0, &b.x1, &b.y0, &b.y1};
    bool ok = parts.size() == 4;
    for (std::size_t i = 0; ok && i < 4; ++i) {
        char* end = nullptr;
        const long v = std::strtol(parts[i].c_str(), &end, 10);
        ok = *end == '\0' && v >= 0 && v <= 65536;
        *fields[i] = int(v);
    }
    if (!ok || b.x0 >= b.x1 || b.y0 >= b.y1)
        throw CLI::ValidationError("--crop",
                                   "expected X0,X1,Y0,Y1 with X0 < X1 and Y0 < Y1 "
                                   "(half-open pixel bounds), e.g. 0,32,0,32, got \"" +
                                       text + "\"");
    return b;
}

}  // namespace lamina::app
