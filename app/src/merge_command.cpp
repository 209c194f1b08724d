// `lamina merge SHARD... -o out.exr`: the image one render of all the shards' samples and
// pixels gives (shard_merge.h), with Variance.R/G/B and Variance.Y, and metadata saying which
// samples it holds.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "lamina/core/printable.h"
#include "lamina/output/image_output.h"
#include "lamina/output/render_metadata.h"
#include "lamina/output/shard_merge.h"
#include "lamina/version.h"

namespace lamina::app {

namespace {

struct MergeArgs {
    std::vector<std::string> shards;
    std::string output;
    bool quiet = false;
};

void runMerge(const MergeArgs& a) {
    const std::filesystem::path output = a.output;
    if (output.extension() != ".exr")
        throw CLI::ValidationError(
            "--output", escapeControl(output.string()) + ": the output is OpenEXR: name it .exr");
    std::vector<std::filesystem::path> inputs(a.shards.begin(), a.shards.end());
    render::checkOutputPath(output, inputs);
    render::MergedShards merged = render::mergeShards(inputs);
    merged.metadata.strings["command_line"] = render::processCommandLine();
    merged.metadata.strings["merge_version"] = LAMINA_VERSION_STRING;
    render::writeExr(output, *merged.film, merged.aovs, merged.metadata, true);
    for (const std::string& w : merged.warnings)
        std::fprintf(stderr, "lamina: warning: %s\n", escapeControl(w).c_str());
    if (!a.quiet)
        std::fprintf(stderr, "%s: %dx%d, %zu shards, samples %s\n", output.string().c_str(),
                     merged.film->width(), merged.film->height(), a.shards.size(),
                     merged.metadata.strings["samples"].c_str());
}

}  // namespace

void registerMergeCommand(CLI::App& app) {
    auto args = std::make_shared<MergeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "Merge shard EXRs (render --samples / --crop) into the image of their union");
    cmd->add_option("shards", args->shards, "Shard EXRs of one scene and settings")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "Merged EXR")->required();
    cmd->add_flag("-q,--quiet", args->quiet, "No summary on stderr (warnings still)");
    cmd->callback([args] { runMerge(*args); });
}

}  // namespace lamina::app
