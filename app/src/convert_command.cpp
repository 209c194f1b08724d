// `lamina convert SCENE -o out.json`: writes the lamina scene a pbrt-v4 or Mitsuba file
// translates to (scene_import.h), for inspection and editing. The document is loaded once
// before it is written, so a file that would not render is refused and nothing is written.
// `lamina convert --check DIR`: a table of every scene file under DIR, what loads and what is
// refused and why (scene_corpus.h).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "lamina/core/output_files.h"
#include "lamina/core/printable.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_corpus.h"
#include "lamina/scene/scene_description.h"

namespace lamina::app {

namespace {

struct ConvertArgs {
    std::string scene;
    std::string output;
    std::string check;
    bool quiet = false;
};

// One row per file: its status, format, warnings or the first line of its error.
void runCheck(const ConvertArgs& a) {
    const auto entries = render::checkSceneCorpus(a.check);
    std::size_t loads = 0;
    std::printf("%-7s  %-7s  %-8s  %s\n", "status", "format", "warnings", "file: why refused");
    for (const auto& e : entries) {
        loads += e.loads ? 1 : 0;
        const std::string format(render::kSceneFormatNames.name(e.format));
        if (e.loads)
            std::printf("%-7s  %-7s  %8zu  %s\n", "loads", format.c_str(), e.warnings,
                        escapeControl(e.file.string()).c_str());
        else
            std::printf("%-7s  %-7s  %8s  %s\n", "refused", format.c_str(), "-",
                        escapeControl(e.error).c_str());
    }
    std::printf("%zu scene files: %zu load, %zu refused\n", entries.size(), loads,
                entries.size() - loads);
}

void runConvert(const ConvertArgs& a) {
    if (!a.check.empty()) {
        if (!a.scene.empty() || !a.output.empty())
            throw CLI::ValidationError("--check", "takes a directory alone: no SCENE or -o");
        runCheck(a);
        return;
    }
    if (a.scene.empty() || a.output.empty())
        throw CLI::ValidationError("convert", "expected SCENE -o out.json, or --check DIR");
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
        "Write the lamina scene a pbrt-v4 (.pbrt) or Mitsuba 3 (.xml) scene translates to, or "
        "(--check DIR) list what loads of every scene file under a directory "
        "(docs/interchange.md)");
    cmd->add_option("scene", args->scene, "A pbrt-v4 or Mitsuba scene file")
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "The lamina scene to write (.json)");
    cmd->add_option("--check", args->check,
                    "A directory: load every .pbrt, .pbrt.gz, .xml and .json file under it and "
                    "print a table of what loads and what is refused, with the first line of why")
        ->check(CLI::ExistingDirectory);
    cmd->add_flag("-q,--quiet", args->quiet, "No summary on stderr (warnings still)");
    cmd->callback([args] { runConvert(*args); });
}

}  // namespace lamina::app
