#include "lamina/scene/lens_file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"

namespace lamina::render {

namespace {

constexpr double kMaxMillimetres = 1e5;
constexpr double kMaxEta = 4;

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
    throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

// One number of a line: strtod on the whole token (std::stod would take "1x" as 1).
double number(const std::string& token, const std::string& name, int line) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(v))
        fail(name, line,
             "expected four finite numbers (radius, thickness, index, aperture "
             "diameter in mm), got \"" +
                 token.substr(0, 40) + "\"");
    return v;
}

}  // namespace

std::vector<LensInterface> parseLensFile(const std::string& text, const std::string& name) {
    if (text.size() > kMaxLensFileBytes)
        throw InputError(name + ": a lens file of more than " + std::to_string(kMaxLensFileBytes) +
                         " bytes");
    std::vector<LensInterface> interfaces;
    std::istringstream lines(text);
    std::string lineText;
    int line = 0, stops = 0;
    while (std::getline(lines, lineText)) {
        ++line;
        if (const auto hash = lineText.find('#'); hash != std::string::npos) lineText.resize(hash);
        std::istringstream tokens(lineText);
        std::vector<std::string> words;
        for (std::string w; tokens >> w && words.size() <= 4;)
            words.push_back(w);
        if (words.empty()) continue;
        if (words.size() != 4)
            fail(name, line,
                 "expected four numbers (radius, thickness, index, aperture "
                 "diameter in mm), got " +
                     std::string(words.size() > 4 ? "more" : std::to_string(words.size())));
        if (interfaces.size() == kMaxLensInterfaces)
            fail(name, line, "more than " + std::to_string(kMaxLensInterfaces) + " interfaces");
        const double radius = number(words[0], name, line),
                     thickness = number(words[1], name, line), eta = number(words[2], name, line),
                     diameter = number(words[3], name, line);
        if (!(std::abs(radius) < kMaxMillimetres))
            fail(name, line, "the curvature radius must be below 1e5 mm in magnitude");
        if (!(thickness >= 0 && thickness < kMaxMillimetres))
            fail(name, line, "the thickness must be in [0, 1e5) mm");
        if (!(diameter > 0 && diameter < kMaxMillimetres))
            fail(name, line, "the aperture diameter must be in (0, 1e5) mm");
        if (!(eta == 0 || (eta >= 1 && eta <= kMaxEta)))
            fail(name, line, "the index of refraction must be 0 (air) or in [1, 4]");
        if (radius == 0 && ++stops > 1)
            fail(name, line, "a second aperture stop (radius 0): a lens system has one");
        if (radius != 0 && std::abs(radius) < diameter / 2)
            fail(name, line,
                 "the aperture diameter is wider than the sphere of its curvature "
                 "radius");
        // Millimetres to metres; index 0 is air.
        interfaces.push_back(
            {radius / 1000, thickness / 1000, eta == 0 ? 1.0 : eta, diameter / 2000});
    }
    if (interfaces.empty()) throw InputError(name + ": a lens file without interfaces");
    return interfaces;
}

std::vector<LensInterface> readLensFile(const std::filesystem::path& file) {
    return parseLensFile(readInputFile(file, kMaxLensFileBytes), file.string());
}

}  // namespace lamina::render
