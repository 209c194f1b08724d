// Error of merged shard sets (`lamina convergence SCENE --merged A.exr,B.exr --reference R`):
// the images `lamina merge` wrote, each measured against a reference (relMSE with epsilon
// 1e-2, MSE, MAE), beside what their metadata says of the work: the number of shards, the
// samples per pixel, the shards' summed render time and the longest shard's (the wall time of
// a farm running all shards at once, before scene loading and the merge). merged.csv and
// summary.md; docs/distributed.md reads these tables.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/report.h"

namespace lamina::experiments {

struct MergedSetInputs {
    std::string scene;  ///< the images must be renders of it (lamina:scene_hash)
    std::vector<std::filesystem::path> images;
    std::string reference;
};

struct MergedSetRow {
    std::filesystem::path image;
    int shards = 0;
    int spp = 0;
    double renderSeconds = 0;   ///< summed over the shards
    double longestSeconds = 0;  ///< of the longest shard
    bool partial = false;
    ImageMetrics metrics;
};

struct MergedSetResult {
    MergedSetInputs inputs;
    std::vector<MergedSetRow> rows;
};

/// InputError if an image is not a merged image of the scene or differs in size from the
/// reference.
MergedSetResult measureMergedSets(const MergedSetInputs& inputs);

void writeMergedSetReport(const MergedSetResult& result, Report& report);

}  // namespace lamina::experiments
