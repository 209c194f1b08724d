#include "lamina/experiments/merged_convergence.h"

#include <cstdio>

#include "lamina/core/error.h"
#include "lamina/output/render_metadata.h"
#include "lamina/scene/scene_description.h"

namespace lamina::experiments {

namespace {

/// The number in metadata key `key` of `image` (read back as text), or InputError.
double number(const render::RgbImage& image, const std::filesystem::path& path,
              const std::string& key) {
    const auto it = image.metadata.find("lamina:" + key);
    if (it == image.metadata.end())
        throw InputError(path.string() + ": lamina:" + key +
                         ": missing (not an image of `lamina merge`)");
    try {
        return std::stod(it->second);
    } catch (const std::exception&) {
        throw InputError(path.string() + ": lamina:" + key + ": expected a number, found \"" +
                         it->second + "\"");
    }
}

}  // namespace

MergedSetResult measureMergedSets(const MergedSetInputs& in) {
    MergedSetResult result;
    result.inputs = in;
    const std::string hash = render::sceneHash(render::loadScene(in.scene));
    const render::RgbImage reference = render::readLinearRgbImage(in.reference);
    for (const auto& path : in.images) {
        const render::RgbImage image = render::readLinearRgbImage(path);
        const auto h = image.metadata.find("lamina:scene_hash");
        if (h == image.metadata.end() || h->second != hash)
            throw InputError(path.string() + ": lamina:scene_hash: not a render of " + in.scene);
        MergedSetRow row;
        row.image = path;
        row.shards = int(number(image, path, "merged_shards"));
        row.spp = int(number(image, path, "spp"));
        row.renderSeconds = number(image, path, "seconds");
        row.longestSeconds = number(image, path, "longest_shard_seconds");
        row.partial = number(image, path, "partial") != 0;
        row.metrics = compareImages(image, reference);
        result.rows.push_back(row);
    }
    return result;
}

void writeMergedSetReport(const MergedSetResult& result, Report& report) {
    std::string csv =
        "image,shards,spp,render_seconds,longest_shard_seconds,partial,relmse,mse,mae\n";
    std::string table =
        "| image | shards | spp | summed render s | longest shard s | relMSE | "
        "relMSE x longest shard s |\n|---|---|---|---|---|---|---|\n";
    char line[512];
    for (const MergedSetRow& r : result.rows) {
        const std::string name = r.image.filename().string();
        std::snprintf(line, sizeof line, "%s,%d,%d,%.6g,%.6g,%d,%.6g,%.6g,%.6g\n", name.c_str(),
                      r.shards, r.spp, r.renderSeconds, r.longestSeconds, r.partial ? 1 : 0,
                      r.metrics.relmse, r.metrics.mse, r.metrics.mae);
        csv += line;
        std::snprintf(line, sizeof line, "| %s%s | %d | %d | %.3g | %.3g | %.3g | %.3g |\n",
                      name.c_str(), r.partial ? " (partial)" : "", r.shards, r.spp, r.renderSeconds,
                      r.longestSeconds, r.metrics.relmse, r.metrics.relmse * r.longestSeconds);
        table += line;
    }
    TablePlot plot;
    plot.title = "relMSE of merged shard sets against the longest shard's render time";
    plot.x = "longest_shard_seconds";
    plot.y = {"relmse"};
    plot.xLabel = "longest shard render time (s)";
    plot.yLabel = "relMSE (epsilon 1e-2)";
    plot.logX = plot.logY = true;
    report.writeTable("merged.csv", csv, plot);
    report.addSummary(
        "# Merged shard sets: " + std::filesystem::path(result.inputs.scene).stem().string() +
        "\n\nEach image measured against " + result.inputs.reference +
        " (relMSE with epsilon 1e-2). An unbiased estimator's relMSE falls as "
        "1/spp, so at equal samples relMSE x longest-shard time falls as 1/N with "
        "N shards running at once.\n\n" +
        table);
}

}  // namespace lamina::experiments
