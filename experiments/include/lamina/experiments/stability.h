// Numerical stability (`lamina stability`): the extreme-input sweep of every model in float and
// double (stability_audit.h) over roughness alpha in kStabilityAlphas and cos(theta_o) in
// kStabilityCosines: a table of NaN, Inf, negative values, energy gain, weight != eval / pdf and
// the worst float/double relative error, and per model two heat maps over (alpha, angle); and
// the polarised case (polarised_stability.h): the Mueller matrices at normal and grazing
// incidence and across Brewster's and the critical angle +-1 ulp.
// With scenes, renders stiff scenes (tiny bright lights, near-smooth glass, grazing views,
// high indices) and reports rejected samples and firefly statistics (the largest sample's
// luminance over the image's mean).
// With a report directory it keeps each finished audit and scene render in DIR/renders/
// (stability_kept.h, kept_renders.h): interrupted, it stops at the next model or render and
// `--resume` continues from what it kept.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lamina/experiments/polarised_stability.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/experiments/result_data.h"
#include "lamina/experiments/stability_audit.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

inline const std::vector<double> kStabilityAlphas = {0, 1e-7, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.5, 1};
inline const std::vector<double> kStabilityCosines = {1, 0.5, 0.1, 1e-2, 1e-4, 1e-6, 1e-8, 0, -0.5};

/// The models audited when none are given: conductors, dielectrics, standard and diffuse.
const std::vector<std::string>& defaultStabilityMaterials();

struct StabilityInputs {
    /// Materials as JSON (empty: the default set); a roughness is replaced by the sweep's alpha.
    std::vector<std::string> materials;
    std::vector<std::string> scenes;  ///< stiff scenes to render
    int spp = 64;                     ///< of the scene renders
    int samples = 4096;               ///< BSDF samples per (alpha, angle) cell
    /// Of the scene renders: --threads, --max-depth and --resolution as given.
    render::RenderOptions overrides;
    /// Where the finished audits and renders are kept (DIR/renders/); empty: nowhere (Python).
    std::filesystem::path keepDirectory;
    bool resume = false;  ///< take back what keepDirectory holds instead of redoing it
    ProgressSink progress;
};

/// The roughness values of the polarised probes (polarised_stability.h): smooth (delta lobes,
/// through sample) and rough (the microfacet Fresnel on the half vector, through eval).
inline const std::vector<double> kPolarisedStabilityAlphas = {0, 0.1};

struct AuditedModel {
    std::string json;
    StabilityReport audit;               ///< one row of alpha (0) for a model without a roughness
    PolarisedStabilityReport polarised;  ///< the Mueller matrices at the singular angles
};

/// A stiff scene's render, path integrator, RGB mode.
struct StiffSceneRender {
    std::string scene;
    std::uint64_t rejectedSamples = 0;
    double largestSample = 0;  ///< luminance
    double meanLuminance = 0;  ///< of the image
};

struct StabilityResult {
    StabilityInputs inputs;
    std::vector<AuditedModel> models;
    std::vector<StiffSceneRender> scenes;
};

/// Interrupted (interrupted.h) between models and renders, carrying as `partial` the models
/// audited so far ({"models": [auditedModelData...], "renders": [...]}).
StabilityResult runStability(const StabilityInputs& inputs);

/// One audited model as data: material, alphas, cosines, issues and worst_float_error over
/// (alpha, cos theta), the totals, and the polarised probes' totals.
Data auditedModelData(const AuditedModel& model);

/// Per model modelN_issues.png and modelN_float_error.png; the summary.
void writeStabilityReport(const StabilityResult& result, Report& report);

}  // namespace lamina::experiments
