// `lamina farm plan`: a render split into N sample-range shards for a batch system. It writes
// a shell script that renders shard INDEX (render-shard.sh INDEX: any batch system that passes
// an index can run it: Slurm's SLURM_ARRAY_TASK_ID, a Kubernetes indexed Job's
// JOB_COMPLETION_INDEX), a merge script, and for Slurm a job-array script, a merge job and
// submit.sh, which submits the array and the merge with --dependency=afterok on the array
// (docs/distributed.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lamina/render/renderer.h"

namespace lamina::experiments {

struct FarmPlanInputs {
    std::filesystem::path scene;       ///< made absolute in the scripts
    std::filesystem::path directory;   ///< where the scripts, shards, logs and image go
    std::filesystem::path executable;  ///< the lamina binary the tasks run
    int shards = 1;
    int spp = 0;                    ///< split into `shards` ranges (or the scene's, when 0)
    std::optional<double> seconds;  ///< instead: every shard renders this long
    /// Passed to every `lamina render` as they are (already validated options: --mode rgb).
    std::vector<std::string> renderArguments;
    int cpusPerTask = 0;  ///< #SBATCH --cpus-per-task (0: not set)
    /// Further #SBATCH directives of both jobs (render and merge), each an sbatch option as
    /// the cluster requires it ("--time=2:00:00", "--partition=gpu", "--account=proj",
    /// "--mem=4G"): see sbatchDirectives.
    std::vector<std::string> sbatchLines;
    std::string jobName = "lamina";
};

/// The sample ranges of the shards: `spp` split as evenly as possible (the first spp % shards
/// ranges get one more sample); with a time budget, shard i starts at i * stride, where stride
/// (2^24, or less for more than 127 shards) bounds the samples one shard may render, so the
/// ranges never overlap.
std::vector<render::SampleRange> planSampleRanges(int shards, int spp, bool timed);

/// The files written, in order: render-shard.sh, merge.sh, render.sbatch, merge.sbatch,
/// submit.sh. InputError if the directory cannot be written.
std::vector<std::filesystem::path> writeFarmPlan(const FarmPlanInputs& in);

/// The options of `lamina farm plan` that become #SBATCH lines: --time-limit, --partition,
/// --account, and any line given as it is (--sbatch, repeated).
struct SbatchOptions {
    std::string timeLimit, partition, account;
    std::vector<std::string> lines;
};

/// The directives of `options` in the order above ("--time=1:00:00", "--partition=short",
/// ...). InputError naming the option for a time limit Slurm would not read (minutes, M:S,
/// H:M:S, D-H, D-H:M or D-H:M:S), or for a line that is not one sbatch option: a line must
/// start with '-' and hold no line break (it is written into the job script as it is).
std::vector<std::string> sbatchDirectives(const SbatchOptions& options);

/// A word quoted for the POSIX shell ('...' with ' written '\'').
std::string shellQuote(const std::string& word);

}  // namespace lamina::experiments
