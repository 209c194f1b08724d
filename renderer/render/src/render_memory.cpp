#include "lamina/render/render_memory.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/integrators/strategy_images.h"
#include "lamina/render/film.h"

namespace lamina::render {

RenderMemory estimateRenderMemory(int width, int height, bool aovs, bool strategies,
                                  int spectralValues, bool splats) {
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    RenderMemory m;
    m.film = pixels * Film::bytesPerPixel();
    m.output = pixels * (aovs ? 11 : 3) * sizeof(float);  // writeExr's channels
    if (strategies) m.strategies = pixels * StrategyImages::bytesPerPixel();
    // Camera sums (and a splat iteration and the splat sums), then the layers' floats.
    m.spectral = pixels * std::uint64_t(spectralValues) *
                 ((splats ? 3 : 1) * sizeof(double) + sizeof(float));
    return m;
}

std::optional<std::uint64_t> availableMemory() {
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        std::string key;
        std::uint64_t kib = 0;
        if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024;
    }
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), size = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && size > 0) return std::uint64_t(pages) * std::uint64_t(size);
    return std::nullopt;
}

std::string formatBytes(std::uint64_t bytes) {
    char text[32];
    const double mib = double(bytes) / double(1 << 20);
    if (mib < 1024)
        std::snprintf(text, sizeof text, "%.1f MiB", mib);
    else
        std::snprintf(text, sizeof text, "%.1f GiB", mib / 1024);
    return text;
}

void checkRenderMemory(const RenderMemory& memory, int width, int height, const std::string& where,
                       std::optional<std::uint64_t> available) {
    if (!available || memory.total() <= *available) return;
    std::string parts =
        "film " + formatBytes(memory.film) + ", image " + formatBytes(memory.output);
    if (memory.strategies) parts += ", strategy images " + formatBytes(memory.strategies);
    if (memory.spectral) parts += ", spectral film " + formatBytes(memory.spectral);
    throw InputError(where + ": " + std::to_string(width) + "x" + std::to_string(height) +
                     " needs ~" + formatBytes(memory.total()) + " (" + parts + "), more than the " +
                     formatBytes(*available) + " of memory available");
}

}  // namespace lamina::render
