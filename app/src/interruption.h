// What SIGINT and SIGTERM do to lamina. Outside a render they end the process at once, after
// removing the temporary files of the writes in progress (nothing half-written stays behind).
// During a render (a RenderInterruption alive) the first one asks the render to stop after the
// pass in flight and lets the image be written; a second one ends the process at once.
#pragma once

#include <functional>
#include <string>

namespace lamina::app {

/// Installs the end-at-once handlers for SIGINT and SIGTERM (main does this first).
void installSignalCleanup();

/// While alive, the first SIGINT or SIGTERM raises render::renderInterruptFlag() instead of
/// ending the process.
class RenderInterruption {
  public:
    RenderInterruption();
    ~RenderInterruption();
    RenderInterruption(const RenderInterruption&) = delete;
    RenderInterruption& operator=(const RenderInterruption&) = delete;

    /// The signal that interrupted the render, 0 if none.
    int signal() const;
    /// The exit status that reports it, as a shell reports a process the signal ended
    /// (128 + the signal: 130 for SIGINT, 143 for SIGTERM).
    int exitStatus() const { return 128 + signal(); }
};

/// Runs an experiment command's `work` (compute, then write the report) under a
/// RenderInterruption. The first SIGINT or SIGTERM during the computation lets the render in
/// flight finish its pass and stops the experiment (experiments::Interrupted): no report is
/// written, since half a computation gives misleading numbers. One during the report's
/// writing lets every file be written. Either way lamina says so on one line and exits with
/// 128 + the signal (CLI::RuntimeError).
void runInterruptible(const std::string& command, const std::function<void()>& work);

}  // namespace lamina::app
