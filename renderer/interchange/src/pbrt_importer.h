// The pbrt-v4 importer's entry point, for scene_import.cpp's table of importers.
#pragma once

#include <filesystem>

#include "lamina/interchange/scene_import.h"

namespace lamina::render::pbrt {

/// Parses a pbrt-v4 file (pbrt_parser.h) and translates it (pbrt_translation.h).
ImportedScene importPbrt(const std::filesystem::path& file,
                         const std::filesystem::path& pathsRelativeTo);

}  // namespace lamina::render::pbrt
