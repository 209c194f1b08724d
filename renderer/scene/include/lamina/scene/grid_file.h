// Density grids of grid media (docs/media.md, "Grid media"): given inline in the scene, or in
// a lamina grid file, a one-line JSON header and the values as raw little-endian float32:
//
//   {"lamina_grid": 1, "size": [nx, ny, nz]}\n<nx * ny * nz float32, x fastest, then y, z>
//
// Every size is checked against the limits below and, for a file, against the file's length
// before anything is allocated, so a bad header costs no memory; every value must be finite
// and >= 0. Errors are one InputError line naming the file and the JSON path or the value.
#pragma once

#include <cstdint>
#include <filesystem>

#include "lamina/scene/density_grid.h"

namespace lamina {
class JsonReader;
}

namespace lamina::render {

/// At most 2^26 values (256 MiB of floats, e.g. 400^3) and 2^16 along an axis.
inline constexpr std::uint64_t kMaxGridValues = std::uint64_t(1) << 26;
inline constexpr int kMaxGridAxis = 1 << 16;
/// The longest header line a grid file may have.
inline constexpr std::size_t kMaxGridHeaderBytes = 4096;

/// A lamina grid file.
DensityGrid readGridFile(const std::filesystem::path& path);

/// A grid given in a scene: {"size": [nx, ny, nz], "values": [...]} (nx * ny * nz numbers).
DensityGrid readInlineGrid(const JsonReader& r);

}  // namespace lamina::render
