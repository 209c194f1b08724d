// `lamina convert SCENE -o out.json`: writes the lamina scene a pbrt-v4 or Mitsuba file
// translates to (scene_import.h), for inspection and editing. The document is loaded once
// before it is written, so a file that would not render is refused and nothing is written.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "lamina/core/output_files.h"
#include "lamina/core/printable.h"
#include "lamina/scene/scene_description.h"
#include "lamina/interchange/scene_import.h"

namespace lamina::app {

namespace {

struct ConvertArgs {
    std::string scene;
    std::string output;
    bool quiet = false;
};

void runConvert(const ConvertArgs& a) {
    const std::filesystem::path output = a.output;
    if (output.extension() != ".json")
        throw CLI::ValidationError("--output", escapeControl(output.string()) +
                                                   ": the output is a lamina scene: name it .json");
    checkOutputFile(output, {a.scene});
    const std::filesystem::path directory =
        output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
    const render::ImportedScene imported = render::importScene(a.scene, directory);
    const std::string text = imported.scene.dump(2) + "\n";
    // The same check `lamina render` makes of the document, with paths resolved where the
    // output will be.
    render::parseScene(text, JsonSource{output.string(), directory});
    writeTextFile(output, text);
    for (const std::string& w : imported.warnings)
        std::fprintf(stderr, "lamina: warning: %s\n", escapeControl(w).c_str());
    if (!a.quiet)
        std::fprintf(stderr, "%s: %s scene, %zu warnings\n", escapeControl(output.string()).c_str(),
                     std::string(render::kSceneFormatNames.name(imported.format)).c_str(),
                     imported.warnings.size());
}

}  // namespace

void registerConvertCommand(CLI::App& app) {
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convert",
        "Write the lamina scene a pbrt-v4 (.pbrt) or Mitsuba 3 (.xml) scene translates to "
        "(docs/interchange.md)");
    cmd->add_option("scene", args->scene, "A pbrt-v4 or Mitsuba scene file")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "The lamina scene to write (.json)")->required();
    cmd->add_flag("-q,--quiet", args->quiet, "No summary on stderr (warnings still)");
    cmd->callback([args] { runConvert(*args); });
}

}  // namespace lamina::app
