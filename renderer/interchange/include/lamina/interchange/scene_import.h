// Scene files of other renderers -> a lamina scene document (docs/scene-format.md), and the
// one entry point that reads a scene file of any supported format (docs/interchange.md).
//
// An importer does one job: it translates a foreign file into the JSON a user could have
// written by hand, plus one warning for every construct it had to map to something else. It
// never builds a SceneDesc itself: the lamina reader (scene_loader.cpp) validates and loads
// the translated document, so every format gets the same checks, limits and provenance. What
// an importer cannot map it refuses with an InputError naming the file and line.
//
// The boundary: importers know file syntax and the meaning of other renderers' parameters;
// they know nothing of Embree, BSDF construction or images.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"
#include "lamina/interchange/scene_format.h"

namespace lamina::render {

/// A translated scene.
struct ImportedScene {
    SceneFormat format = SceneFormat::Lamina;
    /// The lamina scene document. File paths in it (meshes, textures, environment maps) are
    /// relative to the directory `importScene` was given, or absolute.
    Json scene;
    /// "FILE:LINE: what the construct became", one per mapped construct, in reading order.
    std::vector<std::string> warnings;
    /// The scene file and every file it included, in reading order (the provenance hash also
    /// covers the files the lamina reader opens afterwards).
    std::vector<std::filesystem::path> inputFiles;
};

/// The format of `file`: by extension (.json, .pbrt, .xml), else by its first bytes (`{`: lamina;
/// `<`: Mitsuba XML; otherwise pbrt-v4). A missing file is an InputError naming it.
SceneFormat detectSceneFormat(const std::filesystem::path& file);

/// Translates a pbrt-v4 or Mitsuba file into a lamina document whose relative paths are
/// relative to `pathsRelativeTo` (the scene's own directory when rendering; the output's
/// directory for `lamina convert`). A lamina file is refused: it needs no translation.
ImportedScene importScene(const std::filesystem::path& file,
                          const std::filesystem::path& pathsRelativeTo);

/// `path` as it must be written in a document whose paths are relative to `base`: relative
/// when `path` can be reached from `base`, else absolute. Importers write every file path
/// through it.
std::string documentPath(const std::filesystem::path& path, const std::filesystem::path& base);

}  // namespace lamina::render
