// `lamina farm plan SCENE --shards N [--spp S | --time T] -o DIR [--submit]`: the scripts that
// render a scene as N sample-range shards on a batch system and merge them
// (experiments/farm_plan.h); --submit hands them to Slurm.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "lamina/core/error.h"
#include "lamina/experiments/farm_plan.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct FarmPlanArgs {
    std::string scene;
    std::string output;
    int shards = 0;
    int spp = 0;
    double seconds = 0;
    std::string mode;
    std::string integrator;
    std::string resolution;
    long long seed = -1;
    int maxDepth = 0;
    int threads = 0;
    int cpus = 0;
    bool submit = false;
    experiments::SbatchOptions sbatch;
};

void runFarmPlan(const FarmPlanArgs& a) {
    experiments::FarmPlanInputs in;
    in.scene = a.scene;
    in.directory = a.output;
    in.executable = std::filesystem::read_symlink("/proc/self/exe");
    in.shards = a.shards;
    if (a.seconds > 0) in.seconds = a.seconds;
    std::vector<std::string>& r = in.renderArguments;
    if (!a.mode.empty()) r.insert(r.end(), {"--mode", a.mode});
    if (!a.integrator.empty()) r.insert(r.end(), {"--integrator", a.integrator});
    if (!a.resolution.empty()) {
        parseResolution(a.resolution);
        r.insert(r.end(), {"--resolution", a.resolution});
    }
    if (a.seed >= 0) r.insert(r.end(), {"--seed", std::to_string(a.seed)});
    if (a.maxDepth > 0) r.insert(r.end(), {"--max-depth", std::to_string(a.maxDepth)});
    if (a.threads > 0) r.insert(r.end(), {"--threads", std::to_string(a.threads)});
    in.cpusPerTask = a.cpus > 0 ? a.cpus : a.threads;
    in.sbatchLines = experiments::sbatchDirectives(a.sbatch);
    // The samples to split: --spp, or the scene's.
    in.spp = a.spp > 0 ? a.spp : render::loadScene(a.scene).settings.spp;
    const auto files = experiments::writeFarmPlan(in);
    for (const auto& f : files)
        std::printf("%s\n", f.string().c_str());
    if (!a.submit) return;
    const std::string submit = files.back().string();
    std::fflush(stdout);
    const int status = std::system(("bash " + experiments::shellQuote(submit)).c_str());
    if (status != 0)
        throw InputError(submit + ": sbatch failed (exit status " +
                         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) +
                         "); the scripts are written, submit them by hand");
}

}  // namespace

void registerFarmCommand(CLI::App& app) {
    CLI::App* farm =
        app.add_subcommand("farm", "Render on a batch system (Slurm) as sample-range shards");
    farm->require_subcommand(1);
    auto args = std::make_shared<FarmPlanArgs>();
    CLI::App* cmd = farm->add_subcommand(
        "plan", "Write a Slurm job array of shard renders and a dependent merge job");
    cmd->add_option("scene", args->scene, "Scene file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output,
                    "Directory for the scripts, shards/, logs/ and image.exr")
        ->required();
    cmd->add_option("--shards", args->shards, "Number of shards (array tasks)")
        ->required()
        ->check(CLI::Range(1, 100000));
    auto* spp = cmd->add_option("--spp", args->spp,
                                "Samples per pixel to split between the shards (default: the "
                                "scene's)")
                    ->check(CLI::Range(1, 1 << 24));
    cmd->add_option("--time", args->seconds, "Instead: every shard renders this many seconds")
        ->check(positiveNumber("seconds"))
        ->excludes(spp);
    cmd->add_option("--mode", args->mode, "Render mode")
        ->check(CLI::IsMember(render::kRenderModeNames.names()));
    cmd->add_option("--integrator", args->integrator, "Light transport algorithm")
        ->check(CLI::IsMember(render::kIntegratorNames.names()));
    cmd->add_option("--resolution", args->resolution, "Image size WIDTHxHEIGHT (overrides)");
    cmd->add_option("--seed", args->seed, "Random seed (overrides the scene's)")
        ->check(CLI::Range(0LL, 2147483647LL));
    cmd->add_option("--max-depth", args->maxDepth, "Maximum scattering events per path")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--threads", args->threads, "Threads per task (also its --cpus-per-task)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--cpus-per-task", args->cpus, "#SBATCH --cpus-per-task (default: --threads)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--time-limit", args->sbatch.timeLimit,
                    "#SBATCH --time of both jobs: MINUTES, H:M:S or D-H:M:S");
    cmd->add_option("--partition", args->sbatch.partition, "#SBATCH --partition of both jobs");
    cmd->add_option("--account", args->sbatch.account, "#SBATCH --account of both jobs");
    cmd->add_option("--sbatch", args->sbatch.lines,
                    "Any further #SBATCH line of both jobs, e.g. --sbatch=--mem=4G (repeatable)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_flag("--submit", args->submit,
                  "Submit with sbatch: the array, then the merge after it (afterok)");
    cmd->callback([args] { runFarmPlan(*args); });
}

}  // namespace lamina::app
