// A corpus at a glance (`lamina convert --check DIR`): every scene file under a directory
// loaded as `lamina render` would load it, and what became of it: loads (with how many
// warnings), or refused with the first line of its error.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/interchange/scene_format.h"

namespace lamina::render {

struct CorpusEntry {
    std::filesystem::path file;
    SceneFormat format = SceneFormat::Lamina;
    bool loads = false;
    std::size_t warnings = 0;  ///< of a file that loads
    std::string error;         ///< of a refused file: its first line
};

/// Every .pbrt, .pbrt.gz, .xml and .json file under `directory` (recursively, in path order),
/// each loaded once. A directory that cannot be read is an InputError naming it.
std::vector<CorpusEntry> checkSceneCorpus(const std::filesystem::path& directory);

}  // namespace lamina::render
