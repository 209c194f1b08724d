#include "lamina/scene/scene_corpus.h"

#include <algorithm>
#include <new>

#include "lamina/core/error.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

namespace {

bool isSceneFile(const std::filesystem::path& p) {
    const std::string name = p.filename().string();
    const auto endsWith = [&](const std::string& tail) {
        return name.size() >= tail.size() &&
               name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    return endsWith(".pbrt") || endsWith(".pbrt.gz") || endsWith(".xml") || endsWith(".json");
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

}  // namespace

std::vector<CorpusEntry> checkSceneCorpus(const std::filesystem::path& directory) {
    std::error_code ec;
    if (!std::filesystem::is_directory(directory, ec))
        throw InputError(directory.string() + ": not a directory");
    std::vector<std::filesystem::path> files;
    for (auto it = std::filesystem::recursive_directory_iterator(directory, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file() && isSceneFile(it->path())) files.push_back(it->path());
    if (ec) throw InputError(directory.string() + ": " + ec.message());
    std::sort(files.begin(), files.end());

    std::vector<CorpusEntry> entries;
    for (const auto& file : files) {
        CorpusEntry e;
        e.file = file;
        try {
            e.format = detectSceneFormat(file);
            const SceneDesc scene = loadScene(file, false);
            e.loads = true;
            e.warnings = scene.importWarnings.size();
        } catch (const InputError& error) {
            e.error = firstLine(error.what());
        } catch (const std::bad_alloc&) {
            e.error = file.string() + ": out of memory while reading it";
        }
        entries.push_back(std::move(e));
    }
    return entries;
}

}  // namespace lamina::render
