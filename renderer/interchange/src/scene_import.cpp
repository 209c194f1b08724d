// Format detection and the table of importers (scene_import.h). A new format is one entry in
// kImporters and one value in SceneFormat.
#include "lamina/interchange/scene_import.h"

#include <fstream>

#include "lamina/core/error.h"
#include "mitsuba_translation.h"
#include "pbrt_importer.h"

namespace lamina::render {

namespace {

struct Importer {
    SceneFormat format;
    ImportedScene (*translate)(const std::filesystem::path& file,
                               const std::filesystem::path& pathsRelativeTo);
};

// Every importer, by format. lamina's own format needs none.
constexpr Importer kImporters[] = {
    {SceneFormat::Mitsuba, mitsuba::importMitsubaScene},
    {SceneFormat::Pbrt, pbrt::importPbrt},
};

constexpr bool hasImporter(SceneFormat format) {
    for (const Importer& importer : kImporters)
        if (importer.format == format) return true;
    return false;
}

// A format added to SceneFormat without an importer fails here, at compile time, rather than
// with an error a user would meet.
static_assert(hasImporter(SceneFormat::Mitsuba) && hasImporter(SceneFormat::Pbrt),
              "every foreign scene format has an entry in kImporters");

}  // namespace

SceneFormat detectSceneFormat(const std::filesystem::path& file) {
    const std::string extension = file.extension().string();
    if (extension == ".json") return SceneFormat::Lamina;
    if (extension == ".pbrt") return SceneFormat::Pbrt;
    if (extension == ".gz" && file.stem().extension() == ".pbrt") return SceneFormat::Pbrt;
    if (extension == ".xml") return SceneFormat::Mitsuba;
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string() + ": cannot open the scene file");
    // The first character that is not white space decides; pbrt-v4 files start with a
    // directive or a comment.
    char c = 0;
    while (in.get(c))
        if (c != ' ' && c != '\t' && c != '\r' && c != '\n') break;
    if (c == '{') return SceneFormat::Lamina;
    if (c == '<') return SceneFormat::Mitsuba;
    return SceneFormat::Pbrt;
}

ImportedScene importScene(const std::filesystem::path& file,
                          const std::filesystem::path& pathsRelativeTo) {
    const SceneFormat format = detectSceneFormat(file);
    if (format == SceneFormat::Lamina)
        throw InputError(file.string() + ": is a lamina scene already; nothing to convert");
    const Importer* importer = kImporters;
    while (importer->format != format)
        ++importer;  // found: every foreign format has an entry (the static_assert above)
    return importer->translate(file, pathsRelativeTo);
}

std::string documentPath(const std::filesystem::path& path, const std::filesystem::path& base) {
    const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
    const std::filesystem::path relative =
        absolute.lexically_relative(std::filesystem::absolute(base).lexically_normal());
    return relative.empty() ? absolute.generic_string() : relative.generic_string();
}

}  // namespace lamina::render
