// The ranges of the render settings a user overrides: the commands' declarations
// (experiments/src/render_declaration.cpp and the experiments') take them from here, and so
// the command line's options and the Python module's keywords check the same numbers.
#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace lamina::render {

inline constexpr int kMaxSppOverride = 1 << 24;
inline constexpr int kMaxThreadsOverride = 1024;
inline constexpr int kMaxDepthOverride = 1024;
inline constexpr long long kMaxSeedOverride = 2147483647LL;
/// Each side of an image, as the scene's film.resolution (the memory a render needs is
/// checked when it starts, render_memory.h).
inline constexpr int kMaxResolutionOverride = 65536;
/// `render --spectral-film N`: bins no narrower than 1 nm, the resolution of lamina's spectral
/// tables, over the 470 nm the spectral mode samples.
inline constexpr int kMaxSpectralFilmBins = 470;

/// "WIDTHxHEIGHT", each in [1, kMaxResolutionOverride]; nullopt for anything else.
inline std::optional<std::pair<int, int>> parseResolutionText(const std::string& text) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || x != 'x' || w < 1 || h < 1 || w > kMaxResolutionOverride ||
        h > kMaxResolutionOverride || !in.eof())
        return std::nullopt;
    return std::pair{w, h};
}

}  // namespace lamina::render
