// gzip-compressed input files (.ply.gz meshes, .pbrt.gz scene files, as pbrt-v4 scenes ship
// them), decompressed into memory within a bound: a small file that inflates without end (a zip
// bomb) is refused when it passes the bound, not when memory runs out.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace lamina {

/// The file's name ends in .gz.
bool isGzipPath(const std::filesystem::path& file);

/// The decompressed contents of `file` (at most `compressedLimit` bytes on disk and
/// `decompressedLimit` decompressed); InputError naming the file otherwise, or when it cannot
/// be opened ("cannot open the `what` file") or is not valid gzip.
std::string readGzipFile(const std::filesystem::path& file, std::uintmax_t compressedLimit,
                         std::uintmax_t decompressedLimit, const std::string& what);

}  // namespace lamina
