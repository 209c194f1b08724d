#include "interruption.h"

#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>

#include "lamina/core/output_files.h"
#include "lamina/experiments/interrupted.h"
#include "lamina/render/renderer.h"

namespace lamina::app {

namespace {

std::atomic<bool> graceful{false};
std::atomic<int> received{0};

// Only async-signal-safe work here: atomics, unlink (removeTemporaryFilesNow), signal, raise.
void onSignal(int sig) {
    int none = 0;
    if (graceful.load() && received.compare_exchange_strong(none, sig)) {
        render::renderInterruptFlag().store(true);
        return;
    }
    removeTemporaryFilesNow();
    std::signal(sig, SIG_DFL);
    std::raise(sig);  // ends the process with the signal's own status
}

}  // namespace

void installSignalCleanup() {
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

RenderInterruption::RenderInterruption() {
    received.store(0);
    render::renderInterruptFlag().store(false);
    graceful.store(true);
}

RenderInterruption::~RenderInterruption() {
    graceful.store(false);
}

int RenderInterruption::signal() const {
    return received.load();
}

void runInterruptible(const std::string& command, const std::function<void()>& work) {
    const RenderInterruption interruption;
    const auto signalName = [&] { return interruption.signal() == SIGTERM ? "SIGTERM" : "SIGINT"; };
    try {
        work();
    } catch (const experiments::Interrupted& stopped) {
        if (stopped.kept.empty())
            std::fprintf(stderr,
                         "lamina %s: interrupted by %s: stopped before the report, nothing "
                         "written\n",
                         command.c_str(), signalName());
        else
            std::fprintf(stderr,
                         "lamina %s: interrupted by %s: stopped before the report; kept %s\n",
                         command.c_str(), signalName(), stopped.kept.c_str());
        throw CLI::RuntimeError(interruption.exitStatus());
    }
    if (interruption.signal() != 0) {
        std::fprintf(stderr, "lamina %s: interrupted by %s while writing: the report is complete\n",
                     command.c_str(), signalName());
        throw CLI::RuntimeError(interruption.exitStatus());
    }
}

}  // namespace lamina::app
