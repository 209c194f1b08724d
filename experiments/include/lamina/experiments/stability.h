// Numerical stability (`lamina stability`): the extreme-input sweep of every model in float and
// double (stability_audit.h) over roughness alpha in kStabilityAlphas and cos(theta_o) in
// kStabilityCosines: a table of NaN, Inf, negative values, energy gain, weight != eval / pdf and
// the worst float/double relative error, and per model two heat maps over (alpha, angle); and
// the polarised case (polarised_stability.h): the Mueller matrices at normal and grazing
// incidence and across Brewster's and the critical angle +-1 ulp.
// With scenes, renders stiff scenes (tiny bright lights, near-smooth glass, grazing views,
// high indices) and reports rejected samples and firefly statistics (the largest sample's
// luminance over the image's mean).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lamina/experiments/polarised_stability.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/experiments/stability_audit.h"

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

StabilityResult runStability(const StabilityInputs& inputs);

/// Per model modelN_issues.png and modelN_float_error.png; the summary.
void writeStabilityReport(const StabilityResult& result, Report& report);

}  // namespace lamina::experiments
