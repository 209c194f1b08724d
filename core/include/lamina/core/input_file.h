// The one gate every file reader goes through before it reads a byte (scene JSON, OBJ, PLY,
// n/k YAML and CSV, images): the path must name a regular file (a directory, a FIFO or
// /dev/zero would make a reader hang or read until memory runs out) no larger than a limit
// sane for its kind. Errors are InputErrors "FILE: why".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace lamina {

/// Upper bounds on what a reader will read, by kind of file. Far above any real input of the
/// kind, far below what would exhaust the memory of a workstation.
inline constexpr std::uintmax_t kMiB = std::uintmax_t(1) << 20;
inline constexpr std::uintmax_t kMaxTextFileBytes = 256 * kMiB;   ///< JSON, n/k tables
inline constexpr std::uintmax_t kMaxMeshFileBytes = 4096 * kMiB;  ///< OBJ, PLY
inline constexpr std::uintmax_t kMaxImageFileBytes = 4096 * kMiB;
/// Decoded images: 2^27 pixels (e.g. 16384 x 8192), 1.5 GiB as RGB floats.
inline constexpr std::uintmax_t kMaxImagePixels = std::uintmax_t(1) << 27;

/// Throws an InputError unless `path` is an existing regular file (symbolic links followed)
/// of at most `limit` bytes; returns its size.
std::uintmax_t checkInputFile(const std::filesystem::path& path, std::uintmax_t limit);

/// The whole content of a file that passes checkInputFile.
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t limit);

/// Why `path` cannot be read as a regular file ("no such file", "is a directory, not a
/// regular file", ...), or empty when it is one.
std::string notARegularFile(const std::filesystem::path& path);

}  // namespace lamina
