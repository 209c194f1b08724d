// `lamina merge`: adds the sums of shards (shard_file.h) into the film one render of all their
// samples and pixels would have made. The shards must belong together (the same scene hash and
// settings, and no pixel holding a sample index twice); what the union lacks (sample indices
// below its largest, pixels no shard covers, pixels with fewer samples than others) is reported,
// not refused, and named in the merged image's metadata.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "lamina/render/film.h"
#include "lamina/output/image_output.h"

namespace lamina::render {

struct MergedShards {
    std::unique_ptr<Film> film;  ///< the whole image
    ImageMetadata metadata;      ///< the render's keys, with spp and the merge's (samples, ...)
    bool aovs = false;           ///< every shard has the AOV sums (rendered with --aovs)
    std::vector<std::string> warnings;  ///< missing samples or pixels, interrupted shards
};

/// InputError naming the conflicting files if the shards do not belong together.
MergedShards mergeShards(const std::vector<std::filesystem::path>& shards);

/// "0:8,16:8": sample ranges FIRST:COUNT.
std::string sampleRangesText(const std::vector<std::pair<int, int>>& ranges);

}  // namespace lamina::render
