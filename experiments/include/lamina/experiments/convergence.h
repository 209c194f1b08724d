// Error against render time (`lamina convergence`): every combination of integrator and render
// mode renders progressively for the same time; after every pass the image is compared with a
// reference (relMSE with epsilon 1e-2, MSE, MAE). The report: convergence.csv, the figure
// convergence.png/.pdf (log-log relMSE against seconds and against samples, figure_spec.h),
// summary.md (samples per second, final
// errors, the fitted slope of log relMSE against log seconds, which is -1 for an unbiased
// Monte Carlo estimator, and the time each needs to reach given error levels). Before the
// first render the premises of a given reference are checked (convergence_premises.h); each
// finished run is kept (convergence_runs.h) so that an interrupted run can resume.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lamina/experiments/convergence_premises.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/output/render_metadata.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// A relMSE level of the time-to-error columns, with its label as written ("1e-2").
struct ErrorLevel {
    double relmse;
    std::string label;
};

struct ConvergenceInputs {
    std::string scene;  ///< scene file
    /// Every integrator of kIntegratorNames unless chosen.
    std::vector<render::IntegratorKind> integrators = render::kIntegratorNames.values();
    std::vector<render::RenderModeKind> modes = {render::RenderModeKind::Rgb};
    double seconds = 10;  ///< render time of each combination
    std::vector<ErrorLevel> levels = {{1e-2, "1e-2"}, {1e-3, "1e-3"}};
    /// A reference EXR for every mode; empty: one reference per mode is rendered first.
    std::string reference;
    /// Measure against a reference rendered with the measured renders' sampler and seed
    /// anyway (referenceCorrelation): the errors are then understated.
    bool allowCorrelatedReference = false;
    /// Measure against a given reference whose own noise is too large against the runs'
    /// errors (noisePremise) anyway: the summary flags it.
    bool allowNoisyReference = false;
    /// Where finished work is kept: each finished run as runs/INTEGRATOR_MODE.csv
    /// (convergence_runs.h), as soon as it is done; empty: nowhere.
    std::filesystem::path keepDirectory;
    /// Continue the work kept in keepDirectory: its reference_MODE.exr (rendered by an
    /// interrupted run) instead of rendering the reference, and its finished runs instead of
    /// rendering them again.
    bool resume = false;
    render::IntegratorKind referenceIntegrator = render::IntegratorKind::Path;
    double referenceSeconds = 0;  ///< of each rendered reference; 0: 20 x seconds
    /// Applied to every render (threads, sampler, max depth, resolution); the mode, the
    /// integrator and the time are set per render, and a reference always uses Sobol and a
    /// seed of its own.
    render::RenderOptions overrides;
    render::BuildInfo build;  ///< stamped into the rendered references
    ProgressSink progress;
    /// Called with each reference as soon as it is rendered (the command line writes it at
    /// once, so an interrupted run keeps what took longest); nothing when empty.
    std::function<void(const struct RenderedReference&)> onReference;
    /// Called with what was done (references, finished runs, premises) when the experiment
    /// is interrupted, before Interrupted reaches the caller; nothing when empty.
    std::function<void(const struct ConvergenceResult&)> onInterrupted;
};

/// A reference the experiment rendered (one per mode).
struct RenderedReference {
    render::RenderModeKind mode;
    render::RenderResult render;
    render::ImageMetadata metadata;  ///< written into reference_MODE.exr
};

/// Writes reference_MODE.exr into the report's directory, with the variance of every pixel's
/// mean (Variance.R/G/B, Variance.Y: the reference's noise when it is reused); returns its path.
std::filesystem::path writeRenderedReference(const RenderedReference& reference,
                                             const Report& report);

/// One combination's error after every pass.
struct ConvergenceCurve {
    render::IntegratorKind integrator;
    render::RenderModeKind mode;
    ErrorLog log;
    double pathsPerSecond = 0;
    int spp = 0;
    bool resumed = false;  ///< read back from the kept run (resume), not rendered now
};

/// A premise of the measurement of one mode.
struct ModePremise {
    render::RenderModeKind mode;
    Premise premise;
};

struct ConvergenceResult {
    ConvergenceInputs inputs;
    std::vector<RenderedReference> references;  ///< empty when the reference was given
    std::vector<ConvergenceCurve> curves;       ///< modes outer, integrators inner
    /// For the summary: what is known of a given reference's provenance.
    std::string referenceNote;
    /// Every check of every mode's reference, in the order made (the noise of a mode's
    /// reference once its runs are done).
    std::vector<ModePremise> premises;
};

/// Why a given reference is correlated with the measured renders, or nothing. A reference
/// rendered with the same sampler and seed as the measured renders (read from its lamina:seed
/// and lamina:sampler metadata) shares their first samples: pixel by pixel the measured image
/// converges towards the reference's own noise, so the error is understated (about 3x on the
/// Cornell box) and the fitted slope is steeper than -1. A reference without lamina metadata
/// (another renderer) cannot be checked and is not reported.
std::optional<std::string> referenceCorrelation(const render::RgbImage& reference,
                                                const render::SceneDesc& scene,
                                                const render::RenderOptions& measured);

/// What a fitted slope is taken against: the render's seconds (what an equal-time comparison
/// cares about) or its samples per pixel (the estimator's own convergence, which the machine's
/// load cannot bend: on a busy machine the seconds of a pass vary, the samples do not).
enum class SlopeAxis { Seconds, Samples };

/// Least-squares slope of log(relMSE) against log(seconds) or log(spp) over the passes after
/// the first tenth of the run on that axis (the first passes are dominated by start-up costs);
/// NAN with fewer than three such passes. -1 for an unbiased estimator whose error is all
/// variance.
double fittedSlope(const std::vector<ErrorLog::Row>& rows, SlopeAxis axis = SlopeAxis::Seconds);

/// The first time relMSE reaches `level` (log-log interpolation between passes), or NAN.
double timeToReach(const std::vector<ErrorLog::Row>& rows, double level);

ConvergenceResult runConvergence(const ConvergenceInputs& inputs);

/// "reference_rgb.exr": the file of a rendered reference of `mode` in the report's directory.
std::string renderedReferenceName(render::RenderModeKind mode);

/// convergence.csv, the figure convergence, the references rendered (reference_MODE.exr) and
/// the summary (with its Premises section).
void writeConvergenceReport(const ConvergenceResult& result, Report& report);

}  // namespace lamina::experiments
