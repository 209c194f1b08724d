#include "lamina/experiments/farm_plan.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/core/output_files.h"

namespace lamina::experiments {

namespace {

constexpr int kTimedStride = 1 << 24;

void writeScript(const std::filesystem::path& path, const std::string& text) {
    checkOutputFile(path);
    TemporaryFile tmp(path);
    {
        std::ofstream out(tmp.path());
        out << text;
        if (!out) throw InputError(path.string() + ": cannot write");
    }
    ::chmod(tmp.path().c_str(), 0755);
    tmp.commit();
}

std::string bashArray(const std::vector<int>& values) {
    std::string out = "(";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) out += ' ';
        out += std::to_string(values[i]);
    }
    return out + ")";
}

/// sbatch(1), --time: "minutes", "minutes:seconds", "hours:minutes:seconds", "days-hours",
/// "days-hours:minutes" and "days-hours:minutes:seconds": fields of digits.
bool isSlurmTimeLimit(const std::string& text) {
    const std::size_t dash = text.find('-');
    const std::string days = dash == std::string::npos ? "" : text.substr(0, dash);
    const std::string clock = dash == std::string::npos ? text : text.substr(dash + 1);
    const auto digits = [](const std::string& field) {
        return !field.empty() &&
               std::all_of(field.begin(), field.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dash != std::string::npos && !digits(days)) return false;
    int fields = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t colon = clock.find(':', start);
        if (!digits(clock.substr(start, colon - start))) return false;
        ++fields;
        if (colon == std::string::npos) break;
        start = colon + 1;
    }
    return fields <= 3;
}

}  // namespace

std::string shellQuote(const std::string& word) {
    std::string out = "'";
    for (const char c : word) {
        if (c == '\'')
            out += "'\\''";
        else
            out += c;
    }
    return out + "'";
}

std::vector<std::string> sbatchDirectives(const SbatchOptions& options) {
    std::vector<std::string> out;
    if (!options.timeLimit.empty()) {
        if (!isSlurmTimeLimit(options.timeLimit))
            throw InputError("--time-limit " + options.timeLimit +
                             ": expected a Slurm time limit: MINUTES, H:M:S or D-H:M:S");
        out.push_back("--time=" + options.timeLimit);
    }
    const auto named = [&](const char* option, const std::string& value) {
        if (value.empty()) return;
        if (value.find_first_of(" \t\r\n") != std::string::npos)
            throw InputError(std::string(option) + " " + value + ": expected one word");
        out.push_back(std::string(option) + "=" + value);
    };
    named("--partition", options.partition);
    named("--account", options.account);
    for (const std::string& line : options.lines) {
        if (line.rfind('-', 0) != 0 || line.find_first_of("\r\n") != std::string::npos)
            throw InputError("--sbatch " + line +
                             ": expected one sbatch option on one line, such as --mem=4G");
        out.push_back(line);
    }
    return out;
}

std::vector<render::SampleRange> planSampleRanges(int shards, int spp, bool timed) {
    if (shards < 1) throw InputError("--shards: expected at least 1 shard");
    std::vector<render::SampleRange> ranges;
    if (timed) {
        const int stride = std::min(kTimedStride, std::numeric_limits<int>::max() / shards);
        for (int i = 0; i < shards; ++i)
            ranges.push_back({i * stride, stride});
        return ranges;
    }
    if (spp < shards)
        throw InputError("--shards " + std::to_string(shards) + ": more shards than the " +
                         std::to_string(spp) + " samples per pixel to split");
    int first = 0;
    for (int i = 0; i < shards; ++i) {
        const int count = spp / shards + (i < spp % shards ? 1 : 0);
        ranges.push_back({first, count});
        first += count;
    }
    return ranges;
}

std::vector<std::filesystem::path> writeFarmPlan(const FarmPlanInputs& in) {
    checkOutputDirectory(in.directory);
    const auto ranges = planSampleRanges(in.shards, in.spp, in.seconds.has_value());
    std::filesystem::create_directories(in.directory / "shards");
    std::filesystem::create_directories(in.directory / "logs");
    const std::filesystem::path dir = std::filesystem::absolute(in.directory);
    const std::string scene = std::filesystem::absolute(in.scene).string();
    const std::string exe = std::filesystem::absolute(in.executable).string();
    std::vector<int> firsts, counts;
    for (const auto& r : ranges) {
        firsts.push_back(r.first);
        counts.push_back(r.count);
    }
    std::string extra;
    for (const std::string& a : in.renderArguments) {
        extra += ' ';
        extra += shellQuote(a);
    }
    if (in.seconds) {
        std::ostringstream t;
        t.precision(17);
        t << *in.seconds;
        extra += " --time ";
        extra += t.str();
    }
    const std::string n = std::to_string(in.shards);
    std::string shardList;
    for (int i = 0; i < in.shards; ++i)
        shardList += " \"$dir/shards/shard-" + std::to_string(i) + ".exr\"";

    std::vector<std::filesystem::path> files;
    const auto write = [&](const std::string& name, const std::string& text) {
        files.push_back(dir / name);
        writeScript(files.back(), text);
    };
    write("render-shard.sh",
          "#!/bin/bash\n"
          "# Renders shard INDEX (0 to " +
              std::to_string(in.shards - 1) + ") of " + scene +
              ": lamina farm plan wrote this.\n"
              "# Any batch system can run it with the index it passes: Slurm's\n"
              "# SLURM_ARRAY_TASK_ID (render.sbatch), a Kubernetes indexed Job's\n"
              "# JOB_COMPLETION_INDEX, or by hand.\n"
              "set -euo pipefail\n"
              "index=${1:?usage: render-shard.sh INDEX}\n"
              "dir=" +
              shellQuote(dir.string()) +
              "\n"
              "first=" +
              bashArray(firsts) +
              "\n"
              "count=" +
              bashArray(counts) +
              "\n"
              "if ! [[ $index =~ ^[0-9]+$ ]] || (( index >= " +
              n +
              " )); then\n"
              "  echo \"render-shard.sh: index $index: expected 0 to " +
              std::to_string(in.shards - 1) +
              "\" >&2\n"
              "  exit 2\n"
              "fi\n"
              "exec " +
              shellQuote(exe) + " render " + shellQuote(scene) + extra +
              " --samples \"${first[index]}:${count[index]}\" -q \\\n"
              "  -o \"$dir/shards/shard-$index.exr\"\n");
    write("merge.sh",
          "#!/bin/bash\n"
          "# Merges the shards into image.exr once every shard is rendered.\n"
          "set -euo pipefail\n"
          "dir=" +
              shellQuote(dir.string()) +
              "\n"
              "exec " +
              shellQuote(exe) + " merge" + shardList + " -o \"$dir/image.exr\"\n");
    const std::string cpus =
        in.cpusPerTask > 0 ? "#SBATCH --cpus-per-task=" + std::to_string(in.cpusPerTask) + "\n"
                           : "";
    // The cluster's own directives go into both jobs: a partition or account that the site
    // requires is required of the merge job too.
    std::string site;
    for (const std::string& line : in.sbatchLines)
        site += "#SBATCH " + line + "\n";
    write("render.sbatch",
          "#!/bin/bash\n"
          "#SBATCH --job-name=" +
              in.jobName +
              "-render\n"
              "#SBATCH --array=0-" +
              std::to_string(in.shards - 1) + "\n" + cpus + site +
              "#SBATCH --output=" + (dir / "logs" / "render-%a.log").string() +
              "\n"
              "exec " +
              shellQuote((dir / "render-shard.sh").string()) + " \"$SLURM_ARRAY_TASK_ID\"\n");
    write("merge.sbatch",
          "#!/bin/bash\n"
          "#SBATCH --job-name=" +
              in.jobName + "-merge\n" + site +
              "#SBATCH --output=" + (dir / "logs" / "merge.log").string() +
              "\n"
              "exec " +
              shellQuote((dir / "merge.sh").string()) + "\n");
    write("submit.sh",
          "#!/bin/bash\n"
          "# Submits the render array, then the merge to run once every task succeeded.\n"
          "set -euo pipefail\n"
          "dir=" +
              shellQuote(dir.string()) +
              "\n"
              "array=$(sbatch --parsable \"$dir/render.sbatch\")\n"
              "array=${array%%;*}\n"
              "merge=$(sbatch --parsable --dependency=afterok:$array \"$dir/merge.sbatch\")\n"
              "echo \"render array: job $array\"\n"
              "echo \"merge: job ${merge%%;*} (after $array)\"\n");
    return files;
}

}  // namespace lamina::experiments
