// What a convergence measurement assumes of its reference, checked before work starts
// (`lamina convergence`, convergence.h): that the reference is an image of the same thing the
// measured renders converge to (the same mode, resolution, scene files, maximum depth, and no
// setting that converges elsewhere), that it is independent of them, and that its own noise is
// small against their errors. Each check is a Premise with its outcome; the summary lists them
// and Python returns them (`premises`).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/image/image_io.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

enum class PremiseOutcome { Holds, Flagged, NotChecked, Refused };
inline constexpr NameTable kPremiseOutcomeNames{std::array{
    NameEntry{PremiseOutcome::Holds, "holds"}, NameEntry{PremiseOutcome::Flagged, "flagged"},
    NameEntry{PremiseOutcome::NotChecked, "not checked"},
    NameEntry{PremiseOutcome::Refused, "refused"}}};

struct Premise {
    std::string check;  ///< what is checked: "mode", "resolution", "scene", ...
    PremiseOutcome outcome = PremiseOutcome::Holds;
    std::string detail;  ///< what was found, one sentence
};

/// Where the reference of a mode came from.
enum class ReferenceSource {
    Given,     ///< --reference FILE
    Rendered,  ///< rendered by this run, with the measured renders' settings by construction
    Resumed,   ///< reference_MODE.exr that an interrupted run rendered (--resume)
};

/// The reference of one mode as the checks see it: its pixels' size, its lamina metadata
/// ("lamina:KEY" -> text; empty for another renderer's image) and its variance channels.
struct ReferenceFacts {
    std::string name;  ///< the file, for messages
    ReferenceSource source = ReferenceSource::Given;
    int width = 0, height = 0;
    std::map<std::string, std::string> metadata;
    /// The noise floor (referenceNoiseFloor), or nothing without variance channels.
    std::optional<double> noiseFloor;
    /// Where the floor came from ("Variance.R/G/B channels"); without a floor, why there is
    /// none (empty: no variance channels).
    std::string noiseSource;
};

/// The reference in `path` (already read as `image`) with what the premises read of it: size,
/// metadata, and the noise floor from its variance channels (Variance.R/G/B, else Variance.Y for
/// every channel; none for a reference of one sample per pixel, whose channels hold no estimate).
ReferenceFacts readReferenceFacts(const std::string& path, ReferenceSource source,
                                  const render::RgbImage& image);

/// The facts of a reference rendered by the experiment (`name` for messages): its noise from the
/// film's own per-pixel variance of the mean.
ReferenceFacts renderedReferenceFacts(const std::string& name, const render::Film& film,
                                      const render::RgbImage& image);

/// The checks that need no render, for the measured renders of `mode` with the integrators
/// `integrators` and the options `measured` (the overrides of every measured render) on
/// `scene`: mode, resolution, scene, max_depth, settings that converge elsewhere (next-event
/// estimation off with lights that only it can reach). Outcome Refused where the reference
/// cannot score the renders; NotChecked where the reference has no metadata to check against.
/// A rendered reference holds them by construction (one premise "reference" saying so).
std::vector<Premise> referencePremises(const ReferenceFacts& reference,
                                       const render::SceneDesc& scene,
                                       const render::RenderOptions& measured,
                                       render::RenderModeKind mode);

/// The expected relMSE (image_metrics.h, epsilon kRelMseEpsilon) of the exact image scored
/// against a reference with per-channel variance of its mean `variance` (interleaved like the
/// pixels): mean over the channel values of variance / (reference^2 + epsilon). An image's
/// measured relMSE against a noisy reference is its true relMSE plus this floor (the
/// reference's noise is independent of it), so the floor is what no run can go below.
/// Non-finite or negative values are left out; NAN if nothing is left.
double referenceNoiseFloor(const std::vector<float>& reference, const std::vector<float>& variance);

/// The share of a run's final relMSE that the reference's noise may take: with measured relMSE
/// m(t) = a / t + f, the local slope of log m against log t is -(1 - f / m), so at f / m <= 0.1
/// the slope at the end of the run is flattened by at most 0.1 (the fitted slope, over the
/// whole run, by less).
inline constexpr double kMaxReferenceNoiseShare = 0.1;

/// The noise premise of one mode after its runs, from the floor and the smallest final relMSE
/// of the runs: Holds within kMaxReferenceNoiseShare; beyond it Refused for a given reference
/// unless `allowNoisy` (then Flagged), and Flagged for a rendered or resumed one (its own
/// settings made it: the remedy is a longer --reference-time). NotChecked without a floor.
///
/// `consequence`: what the premise says such noise does (`convergence`'s fitted slopes by
/// default) and how a rendered reference is made quieter.
struct NoiseConsequence {
    bool flattensSlopes = true;  ///< the measurement fits slopes: say how far they flatten
    std::string otherwise;       ///< what it does instead (without slopes)
    std::string quieter = "a longer --reference-time makes a quieter reference";
};
Premise noisePremise(const ReferenceFacts& reference, double smallestFinalRelMse, bool allowNoisy,
                     const NoiseConsequence& consequence = {});

/// "mode rgb: " and the premise's check and detail in one line (messages, the summary).
std::string describePremise(const Premise& premise);

}  // namespace lamina::experiments
