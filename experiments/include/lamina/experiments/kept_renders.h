// The finished renders of an experiment kept in its report's directory (DIR/renders/NAME.exr),
// so that an experiment stopped by SIGINT or SIGTERM (interrupted.h) keeps what it rendered and
// `--resume` continues from it instead of rendering it again (`convergence` keeps its reference
// and runs its own way, convergence_runs.h).
//
// Each render is kept as a shard file (shard_file.h): every per-pixel sum of the film (a
// polarised film's Stokes sums too), the scene files' hash and the line of settings that decide
// a pixel's numbers. A kept render is taken back only for a render of the same scene files,
// settings (mode, integrator, sampler, seed, max depth, resolution, ...) and sample count, and
// refused on one line naming the first that differs. The experiment computes from the film read
// back from the file also where it has just rendered it, so a resumed run and an uninterrupted
// one compute from the same numbers and report the same.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lamina/experiments/interrupted.h"
#include "lamina/experiments/progress.h"
#include "lamina/image/image_io.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// "renders/NAME.exr": a kept render's file under the report's directory.
std::filesystem::path keptRenderFile(const std::string& name);

class KeptRenders {
  public:
    /// Keeps nothing: every render is rendered (Python, which writes no files).
    KeptRenders() = default;
    /// Keeps each render in `directory`/renders/; with `resume`, takes back those there.
    KeptRenders(std::filesystem::path directory, bool resume);

    /// The render `name` ("polarised", "path_batch03": a file name) of `scene` with `options`
    /// (a fixed sample count, no time budget): taken back from its file when resuming and the
    /// file is there, else rendered (renderWhole: Interrupted on a signal) and kept. `progress`
    /// is told "rendering WHAT..." or "WHAT: kept from renders/NAME.exr" (nothing if `what` is
    /// empty). InputError naming the file if it holds another render.
    render::RenderResult render(const std::string& name, const render::SceneDesc& scene,
                                const render::RenderOptions& options, const ProgressSink& progress,
                                const std::string& what);

    /// Adds to `stopped` what this run has: `kept`, the files it wrote and how to resume from
    /// them, and `partial`, the finished renders as data ({"renders": [{name, mode,
    /// integrator, seed, spp, rgb}, ...]}, rgb an (H, W, 3) array of linear Rec.709).
    void describe(Interrupted& stopped) const;

  private:
    struct Finished {
        std::string name, mode, integrator;
        std::uint64_t seed = 0;
        int spp = 0;
        render::RgbImage image;
    };
    std::filesystem::path directory_;  ///< empty: keeps nothing
    bool resume_ = false;
    std::vector<std::filesystem::path> written_;
    std::vector<Finished> finished_;
};

/// Runs `work` and, if it is interrupted, describes in the Interrupted what `kept` has.
template <typename Work>
auto keepingOnInterrupt(const KeptRenders& kept, Work&& work) {
    try {
        return work();
    } catch (Interrupted& stopped) {
        kept.describe(stopped);
        throw;
    }
}

/// Removes `directory`/renders/ once the report is written: its renders are in the report, or
/// were means to it, and a complete report needs no resume.
void removeKeptRenders(const std::filesystem::path& directory);

}  // namespace lamina::experiments
