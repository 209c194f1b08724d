#include "lamina/output/shard_merge.h"

#include <algorithm>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/output/shard_file.h"

namespace lamina::render {

namespace {

/// The first word ("key=value") in which two settings lines differ.
std::pair<std::string, std::string> firstDifference(const std::string& a, const std::string& b) {
    std::istringstream ia(a), ib(b);
    std::string wa, wb;
    while (true) {
        const bool ha = bool(ia >> wa), hb = bool(ib >> wb);
        if (!ha && !hb) return {a, b};
        if (!ha) wa = "(nothing)";
        if (!hb) wb = "(nothing)";
        if (wa != wb || !ha || !hb) return {wa, wb};
    }
}

std::string boundsText(const PixelBounds& b) {
    return std::to_string(b.x0) + "," + std::to_string(b.x1) + "," + std::to_string(b.y0) + "," +
           std::to_string(b.y1);
}

/// The sample indices a shard holds: [first, first + done) (an interrupted shard holds the
/// start of its range).
std::pair<int, int> heldRange(const ShardFile& s) {
    return {s.requested.first, s.requested.first + s.samplesDone};
}

/// Sorted, disjoint [begin, end) intervals covering `ranges`.
std::vector<std::pair<int, int>> unionOf(std::vector<std::pair<int, int>> ranges) {
    std::sort(ranges.begin(), ranges.end());
    std::vector<std::pair<int, int>> out;
    for (const auto& r : ranges) {
        if (r.first >= r.second) continue;
        if (!out.empty() && r.first <= out.back().second)
            out.back().second = std::max(out.back().second, r.second);
        else
            out.push_back(r);
    }
    return out;
}

}  // namespace

std::string sampleRangesText(const std::vector<std::pair<int, int>>& ranges) {
    std::string out;
    for (const auto& [begin, end] : ranges) {
        if (!out.empty()) out += ',';
        out += std::to_string(begin);
        out += ':';
        out += std::to_string(end - begin);
    }
    return out;
}

MergedShards mergeShards(const std::vector<std::filesystem::path>& paths) {
    if (paths.empty()) throw InputError("merge: expected at least one shard");
    std::vector<ShardFile> shards;
    for (const auto& p : paths)
        shards.push_back(readShardExr(p));

    const ShardFile& first = shards.front();
    for (const ShardFile& s : shards) {
        const std::string pair = first.path.string() + " and " + s.path.string();
        if (s.sceneHash != first.sceneHash)
            throw InputError(pair + ": different scenes (scene hash " + first.sceneHash + " and " +
                             s.sceneHash + ")");
        if (s.settings != first.settings) {
            const auto [a, b] = firstDifference(first.settings, s.settings);
            throw InputError(pair + ": different settings (" + a + " and " + b + ")");
        }
    }
    for (std::size_t i = 0; i < shards.size(); ++i)
        for (std::size_t j = i + 1; j < shards.size(); ++j) {
            const auto [a0, a1] = heldRange(shards[i]);
            const auto [b0, b1] = heldRange(shards[j]);
            const int o0 = std::max(a0, b0), o1 = std::min(a1, b1);
            if (o0 < o1 && shards[i].crop.overlaps(shards[j].crop))
                throw InputError(shards[i].path.string() + " and " + shards[j].path.string() +
                                 ": both hold samples " + std::to_string(o0) + ":" +
                                 std::to_string(o1 - o0) + " of pixels in " +
                                 boundsText(shards[i].crop) + " and " + boundsText(shards[j].crop) +
                                 " (X0,X1,Y0,Y1)");
        }

    const int width = first.fullWidth, height = first.fullHeight;
    MergedShards out;
    out.film = std::make_unique<Film>(width, height, first.film->space());
    // The layers of the shards (equal settings: the same mode, integrator and spectral film).
    if (first.film->hasStokes()) out.film->enableStokes();
    if (const SpectralFilm* s = first.film->spectralFilm())
        out.film->enableSpectralFilm(s->bins(), s->components(), s->splats());
    std::vector<long long> held(std::size_t(width) * height, 0);
    std::vector<std::pair<int, int>> ranges;
    std::string partialShards;
    double seconds = 0, longest = 0;
    long long rejected = 0;
    for (const ShardFile& s : shards) {
        const PixelBounds& c = s.crop;
        addFilmSums(*out.film, *s.film);
        for (int y = 0; y < c.height(); ++y)
            for (int x = 0; x < c.width(); ++x)
                held[std::size_t(c.y0 + y) * width + std::size_t(c.x0 + x)] += s.samplesDone;
        ranges.push_back(heldRange(s));
        seconds += s.seconds;
        longest = std::max(longest, s.seconds);
        if (s.metadata.ints.contains("rejected_samples"))
            rejected += s.metadata.ints.at("rejected_samples");
        if (s.partial) {
            if (!partialShards.empty()) partialShards += ',';
            partialShards += s.path.filename().string();
        }
    }

    const auto present = unionOf(ranges);
    long long total = 0;
    std::vector<std::pair<int, int>> missing;
    int previous = 0;
    for (const auto& [begin, end] : present) {
        total += end - begin;
        if (begin > previous) missing.emplace_back(previous, begin);
        previous = end;
    }
    long long incomplete = 0;
    for (const long long h : held)
        if (h < total) ++incomplete;

    if (!missing.empty())
        out.warnings.push_back("no shard holds samples " + sampleRangesText(missing));
    if (incomplete > 0)
        out.warnings.push_back(std::to_string(incomplete) + " of " + std::to_string(held.size()) +
                               " pixels hold fewer than the " + std::to_string(total) +
                               " samples of the others (a crop is missing or ranges differ "
                               "between crops)");
    if (!partialShards.empty())
        out.warnings.push_back("interrupted shards (merged with the samples they hold): " +
                               partialShards);

    ImageMetadata& m = out.metadata;
    m = first.metadata;
    for (const char* key :
         {"shard", "shard_settings", "sample_first", "sample_count", "samples_done", "crop",
          "full_width", "full_height", "film_space", "command_line", "time_budget"}) {
        m.strings.erase(key);
        m.ints.erase(key);
        m.floats.erase(key);
    }
    m.ints["spp"] = int(total);
    m.strings["samples"] = sampleRangesText(present);
    // EXR drops empty strings: "none" says there is nothing to name.
    m.strings["samples_missing"] = missing.empty() ? "none" : sampleRangesText(missing);
    m.ints["incomplete_pixels"] = int(std::min<long long>(incomplete, 1 << 30));
    m.ints["merged_shards"] = int(shards.size());
    m.ints["partial"] = partialShards.empty() ? 0 : 1;
    m.strings["partial_shards"] = partialShards.empty() ? "none" : partialShards;
    // The shards' render times: summed (the work), and the longest (the wall time of a farm
    // that runs every shard at once, without scene loading and the merge).
    m.floats["seconds"] = float(seconds);
    m.floats["longest_shard_seconds"] = float(longest);
    m.ints["rejected_samples"] = int(std::min<long long>(rejected, 1 << 30));
    out.aovs = first.settings.find(" aovs=1") != std::string::npos;
    return out;
}

}  // namespace lamina::render
