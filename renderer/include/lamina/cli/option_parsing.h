// Option values the commands share: comma-separated lists, integrator and mode names, image
// sizes. Errors are CLI::ValidationError naming the option (exit status 2).
#pragma once

#include <CLI/CLI.hpp>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "lamina/render/renderer.h"

namespace lamina::cli {

inline std::vector<std::string> splitList(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

inline render::IntegratorKind integratorByName(const std::string& name,
                                               const std::string& option = "--integrator") {
    if (name == "path") return render::IntegratorKind::Path;
    if (name == "light") return render::IntegratorKind::Light;
    if (name == "bdpt") return render::IntegratorKind::Bdpt;
    throw CLI::ValidationError(option,
                               "unknown integrator \"" + name + "\"; expected path, light, bdpt");
}

inline render::RenderModeKind modeByName(const std::string& name,
                                         const std::string& option = "--mode") {
    if (name == "rgb") return render::RenderModeKind::Rgb;
    if (name == "spectral") return render::RenderModeKind::Spectral;
    throw CLI::ValidationError(option, "unknown mode \"" + name + "\"; expected rgb, spectral");
}

/// "WIDTHxHEIGHT".
inline std::pair<int, int> parseResolution(const std::string& text) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || x != 'x' || w < 1 || h < 1 || !in.eof())
        throw CLI::ValidationError("--resolution", "expected WIDTHxHEIGHT, e.g. 512x512");
    return {w, h};
}

}  // namespace lamina::cli
