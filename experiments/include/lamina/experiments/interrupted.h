// Experiments stopped by SIGINT or SIGTERM (render::renderInterruptFlag, raised by the command
// line's handler). An experiment's results are whole or not at all: a render cut short, or a
// sweep stopped half-way, would give numbers that mislead (a reference with too few samples, a
// verdict on half the batches). So the render in flight finishes its pass, and the experiment
// throws Interrupted from its next check instead of returning; the caller writes no report.
// What was finished whole (a rendered reference, a finished run) is kept: named in `kept` on
// the command line, carried as `partial` to Python.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "lamina/experiments/result_data.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

struct Interrupted : std::runtime_error {
    Interrupted() : std::runtime_error("the experiment was interrupted") {}
    /// What the experiment wrote before it stopped, which a rerun can use ("DIR/reference_rgb.exr
    /// (pass it as --reference ...)"); empty: nothing.
    std::string kept;
    /// What the experiment had done, as its result's data (Python's KeyboardInterrupt carries
    /// it as .partial); nothing where the experiment keeps nothing.
    std::optional<Data> partial;
};

/// Throws Interrupted if the interrupt flag is raised.
void stopIfInterrupted();

/// render::renderScene for an experiment: Interrupted instead of a render cut short.
render::RenderResult renderWhole(
    const render::SceneDesc& scene, const render::RenderOptions& options,
    const std::function<void(const render::RenderProgress&)>& progress = {});

}  // namespace lamina::experiments
