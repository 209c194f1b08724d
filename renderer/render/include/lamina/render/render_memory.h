// The memory a render allocates per pixel, estimated before anything is allocated: the film
// (with its AOV sums and splat layer), the float copy image output makes, and BDPT's
// per-strategy images. A resolution whose estimate exceeds the memory available is refused up
// front instead of failing with std::bad_alloc (or swapping) in the middle of a render.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace lamina::render {

struct RenderMemory {
    std::uint64_t film = 0;        ///< Film: sums, variance sums, AOVs, splat layer
    std::uint64_t output = 0;      ///< the float image image_output writes from
    std::uint64_t strategies = 0;  ///< StrategyImages (bdpt --strategies), else 0
    std::uint64_t spectral = 0;    ///< the spectral film's sums and its layers' floats, else 0
    std::uint64_t total() const { return film + output + strategies + spectral; }
};

/// `spectralValues`: the spectral film's bins times Stokes components per pixel (0: none);
/// `splats`: the integrator splats (the spectral film then keeps a splat layer too).
RenderMemory estimateRenderMemory(int width, int height, bool aovs, bool strategies,
                                  int spectralValues = 0, bool splats = false);

/// The memory the system can give without swapping: MemAvailable of /proc/meminfo, else the
/// free physical pages (sysconf); nullopt when neither is known.
std::optional<std::uint64_t> availableMemory();

/// "1.5 GiB", "12.0 MiB".
std::string formatBytes(std::uint64_t bytes);

/// Throws InputError "<where>: WIDTHxHEIGHT needs ~N GiB (...), more than the M GiB available"
/// when the estimate exceeds `available`.
void checkRenderMemory(const RenderMemory& memory, int width, int height, const std::string& where,
                       std::optional<std::uint64_t> available = availableMemory());

}  // namespace lamina::render
