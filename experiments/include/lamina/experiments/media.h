// What spectral rendering and spectral MIS do for chromatic participating media (`lamina
// media`, docs/media.md). For each scene (which must have media):
//
//  - RGB against spectral. The scene rendered in spectral mode (the reference of the
//    comparison: a chromatic medium's transmittance exp(-sigma_t(lambda) d) per wavelength) and
//    in RGB mode (exp(-sigma_t d) per channel, which is not the channel's average of the
//    spectral transmittances) with the same seed and samples. Reported: per pixel the
//    relative difference of the luminance (polarisation.h's symmetric one) and the CIEDE2000,
//    their mean and 95th percentile against their noise floors (noise_floor.h): both modes are
//    rendered again with a second seed, and the two pairs give the noise of the modes'
//    difference (pairedNoise); beside it, the same statistic between the two independent
//    spectral renders (the floor of two independent renders). Within its floor a difference is
//    "not resolved at this sample count".
//  - Spectral MIS against its ablation. The spectral render again with the spectral MIS over
//    the wavelengths switched off (TransportAblations::noMediaSpectralMis: each wavelength
//    weighted by the hero's free-flight density alone), with the same seed and samples; both
//    are scored against a converged spectral reference (relMSE, image_metrics.h) and their
//    efficiency is 1 / (relMSE x render seconds). The reference is rendered by the experiment
//    with its own seed at `referenceSpp` (default kReferenceSppFactor x spp), or given
//    (`reference`, one scene only); its premises are checked as `convergence` checks them
//    (convergence_premises.h: mode, resolution, scene files, max depth, integrator settings,
//    independence, and its own noise at most kMaxReferenceNoiseShare of the smaller relMSE);
//    a given reference that fails one is refused, a rendered one that is too noisy is flagged.
//
// Every render is kept in the report's directory as it finishes and taken back by a resumed run
// (kept_renders.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/experiments/convergence_premises.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// The rendered reference's samples per pixel, relative to the measured renders': its noise
/// is then about 1/16 of their variance, well within kMaxReferenceNoiseShare of the smaller
/// relMSE when the estimators are comparable.
inline constexpr int kReferenceSppFactor = 16;

struct MediaInputs {
    std::vector<std::string> scenes;
    int spp = 0;           ///< of the compared renders; 0: each scene's
    int referenceSpp = 0;  ///< of a rendered reference; 0: kReferenceSppFactor x spp
    /// A converged spectral render of the (one) scene; empty: rendered.
    std::string reference;
    /// Score against a given reference whose noise is beyond kMaxReferenceNoiseShare anyway.
    bool allowNoisyReference = false;
    /// --resolution, --threads, --max-depth, --seed, --integrator of every render (the
    /// reference's seed is derived from the seed).
    render::RenderOptions overrides;
    ProgressSink progress;
    /// Where the renders are kept as they finish (empty: nowhere), and whether those already
    /// there are taken back (kept_renders.h).
    std::filesystem::path keepDirectory;
    bool resume = false;
};

/// One estimator's render scored against the converged reference.
struct ScoredRender {
    render::RenderResult render;
    ImageMetrics metrics;   ///< against the reference (relmse with its standard error)
    double efficiency = 0;  ///< 1 / (relMSE x seconds); 0 without error or time
};

struct MediaSceneResult {
    std::string scene;  ///< as given
    std::string name;   ///< the report's file prefix: the scene's stem, made unique
    int width = 0, height = 0, spp = 0;

    /// RGB against spectral, both of the first seed. `relative` is NaN where both are black.
    render::RenderResult rgb;
    ImageMetrics rgbMetrics;  ///< RGB against spectral
    FlooredMap relative, ciede2000;
    /// The same statistics between the two independent spectral renders (the two seeds): the
    /// floor two independent renders would have, for comparison.
    struct IndependentPair {
        double meanRelative = 0, p95Relative = 0, meanDeltaE = 0, p95DeltaE = 0;
    } independent;
    std::size_t comparedPixels = 0;  ///< not black in both renders

    /// The spectral render with spectral MIS (the comparison's reference too) and without.
    ScoredRender spectralMis, heroOnly;
    render::RgbImage reference;  ///< the converged reference
    std::string referenceName;   ///< the file given, or "rendered (N spp)"
    int referenceSpp = 0;        ///< 0: unknown (a given file without lamina:spp)
    double referenceSeconds = 0;
    std::vector<Premise> premises;  ///< of the reference, in the order checked
};

struct MediaResult {
    std::vector<MediaSceneResult> scenes;
};

MediaResult runMedia(const MediaInputs& inputs);

/// Per scene the renders (PNG), the image pairs, the relative difference, CIEDE2000 and error
/// figures, media.csv (one row per scene and estimator) and summary.md with the premises.
void writeMediaReport(const MediaResult& result, Report& report);

}  // namespace lamina::experiments
