// How close the analytic layered stacks come to the random-walk `coated` material
// (`lamina layering`, docs/experiments/layering/).
//
// For each coated material, its analytic twins (layering_twins.h: the `layered` stack with the
// same interface and base, once with the article's (1 - F) coupling and once with the albedo
// coupling) against the walk, in RGB mode, double precision, on the luminance (Rec.709 Y):
//  - directional albedo against theta_o (sample() weights averaged: the walk's includes every
//    path, delta reflection of a smooth coat included);
//  - the lobe f |cos theta_i| in the plane of incidence at several theta_o (eval());
//  - the relative error over (theta_o, theta_i), wi in the plane of incidence on the mirror side;
//  - optionally a test-object scene rendered with the walk and with each twin in RGB and
//    spectral mode at equal spp, and the CIEDE2000 difference per pixel.
// Every walk value is the mean of `estimates` independent estimates (each the walk's own
// average of the material's `samples` walks) with its standard error; the twins' albedo is
// estimated the same way, their eval is exact. Comparisons are classified by
// layering_statistics.h.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lamina/experiments/layering_statistics.h"
#include "lamina/experiments/layering_twins.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/output/image_output.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// theta_o of the albedo curve: 0, 5, ..., 85 degrees.
inline constexpr int kLayeringAlbedoStep = 5;
/// theta_o of the lobes, degrees.
inline const std::vector<double> kLayeringLobeAngles = {0, 30, 60, 75};
/// The lobe's signed theta_i: -88 .. 88 degrees in steps of 2 (positive: the mirror side).
inline constexpr int kLayeringLobeStep = 2;
/// The error map's theta_o and theta_i: 0, 5, ..., 85 degrees.
inline constexpr int kLayeringMapStep = 5;
/// The name of the material a test-object scene must define; the experiment replaces it.
inline constexpr const char* kLayeringSceneMaterial = "sample";

struct LayeringInputs {
    /// Coated materials: JSON object literals, "@file.json" or built-in names
    /// (layeringMaterialNames()).
    std::vector<std::string> materials;
    int estimates = 4096;         ///< independent walk estimates per eval point
    int albedoSamples = 1 << 16;  ///< sample() calls per albedo point, walk and twins alike
    std::uint64_t seed = 1;
    std::string scene;  ///< optional: a test-object scene with a material "sample"
    int spp = 0;        ///< of the scene renders (0: the scene's), equal for every render
    std::optional<std::pair<int, int>> resolution;  ///< of the scene renders (none: the scene's)
    ProgressSink progress;
    /// Where the scene renders are kept as they finish (empty: nowhere), and whether those
    /// already there are taken back (kept_renders.h). The walk's and twins' estimates are
    /// computed again by a resumed run (the same numbers: they depend on the seed alone).
    std::filesystem::path keepDirectory;
    bool resume = false;
};

/// One twin (or the walk) on one curve or map: per point the estimate and, for a twin, the
/// comparison with the walk at the same point.
struct LayeringValues {
    std::vector<MeanEstimate> values;
    std::vector<TwinComparison> comparisons;  ///< empty for the walk
    BandCounts counts;
};

/// A render of the test object with one BSDF, in one mode.
struct LayeringRender {
    std::shared_ptr<const render::Film> film;
    render::RgbImage image;  ///< the film's image
    double seconds = 0;
    int spp = 0;
};

/// A twin's render against the walk's in one mode.
struct LayeringRenderComparison {
    std::vector<float> ciede2000;  ///< per pixel
    double meanDeltaE = 0, p95DeltaE = 0;
};

struct LayeringTwinResult {
    std::string name;  ///< "fresnel coupling", "albedo coupling"
    std::string json;  ///< the twin as a material
    LayeringValues albedo;
    std::vector<LayeringValues> lobes;    ///< per kLayeringLobeAngles
    LayeringValues map;                   ///< row-major: theta_o rows, theta_i columns
    std::vector<LayeringRender> renders;  ///< rgb, spectral (with a scene)
    std::vector<LayeringRenderComparison> renderErrors;  ///< rgb, spectral
};

struct LayeringMaterialResult {
    std::string stem;          ///< file names of the report
    std::string json;          ///< the material as given (a built-in: its definition)
    int walksPerEstimate = 1;  ///< the material's `samples`
    /// The material's `max_depth`: 0 when its walk has no cap (the unbiased truth); otherwise
    /// paths of more events are absorbed, the walk is biased low and the report says so.
    int walkMaxDepth = 0;
    std::string twinNote;  ///< why there is no twin, or what the twins leave out
    LayeringValues walkAlbedo;
    std::vector<LayeringValues> walkLobes;
    LayeringValues walkMap;
    std::vector<LayeringRender> walkRenders;  ///< rgb, spectral
    /// rgb, spectral: the walk's render against a second one with another seed, the noise
    /// floor of every twin's CIEDE2000 (noise_floor.h). The twins share the walk's seed, so
    /// their noise is partly correlated with it and this floor is an upper bound of theirs.
    std::vector<LayeringRenderComparison> walkNoise;
    std::vector<LayeringTwinResult> twins;
};

struct LayeringResult {
    LayeringInputs inputs;
    std::vector<LayeringMaterialResult> materials;
    int renderSpp = 0;
    std::vector<double> albedoAngles, lobeAngles, mapAngles;  ///< degrees
};

/// Why a walk capped at `maxDepth` events is not the truth (the report and the console say it
/// wherever such a walk is compared).
std::string cappedWalkNote(int maxDepth);

LayeringResult runLayering(const LayeringInputs& inputs);

/// Per material CSVs and figures (albedo, lobes, error maps, renders), and summary.md.
void writeLayeringReport(const LayeringResult& result, Report& report);

}  // namespace lamina::experiments
