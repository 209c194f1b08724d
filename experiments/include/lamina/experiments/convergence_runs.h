// A finished run of `lamina convergence` kept on disk (DIR/runs/INTEGRATOR_MODE.csv), so that
// an interrupted experiment resumes (--resume) from the runs it finished instead of rendering
// them again. The file holds the run's rows at full precision and the settings its errors
// depend on; a run is taken back only where every setting is the same, so a resumed result
// equals an uninterrupted one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lamina/experiments/convergence.h"

namespace lamina::experiments {

/// The settings a run's errors depend on besides its integrator and mode, as key and value:
/// the time budget, the scene files' hash, max_depth, resolution, sampler, seed, and the
/// reference the rows were measured against (its size and the sum of its pixels).
using RunSettings = std::vector<std::pair<std::string, std::string>>;

RunSettings runSettings(const ConvergenceInputs& inputs, const render::SceneDesc& scene,
                        const render::RgbImage& reference);

/// "runs/path_rgb.csv": a run's file under the report's directory.
std::filesystem::path runFile(render::IntegratorKind integrator, render::RenderModeKind mode);

/// Writes the run into `directory`/runFile(...) (a temporary renamed: never half a file).
void writeRunFile(const std::filesystem::path& directory, const ConvergenceCurve& run,
                  const RunSettings& settings);

/// The run of `integrator` and `mode` kept in `directory`, measured against `reference`, or
/// nothing if there is none. InputError naming the file if it cannot be read, or if it was
/// rendered with other settings than `settings` (naming the first that differs).
std::optional<ConvergenceCurve> readRunFile(const std::filesystem::path& directory,
                                            render::IntegratorKind integrator,
                                            render::RenderModeKind mode,
                                            const RunSettings& settings,
                                            const render::RgbImage& reference);

}  // namespace lamina::experiments
