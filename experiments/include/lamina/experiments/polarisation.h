// What ignoring polarisation costs in a scene (`lamina polarisation`): the scene rendered in the
// polarised mode (Stokes vectors and Mueller matrices, docs/polarisation.md), in the spectral
// mode (s and p averaged at every event) and in the RGB mode, with the same seed, samples and
// settings, so that the polarised and the spectral render differ by polarisation and by noise
// alone, and the RGB render also by its colour and Fresnel approximations.
//
// Reported for each unpolarised mode: per pixel the relative difference of the luminance,
// |Y_mode - Y_polarised| / ((Y_mode + Y_polarised) / 2) (symmetric, in [0, 2]; pixels black in
// both left out, black being at most 1e-6 of the brightest pixel: light cancelled to float
// rounding), and the CIEDE2000 of the mode's render against the polarised one; the mean and 95th
// percentile of each, read against their noise floors (noise_floor.h): every mode is rendered
// again with another seed, and the two pairs give the noise of the modes' difference
// (pairedNoise), as in `fresnel --scene`. The renders are kept in the report's directory as they
// finish and taken back by a resumed run (kept_renders.h). And the polarisation of
// the light reaching the camera, from the polarised render's Stokes layers (luminance of each
// component, in the image frame): the degree of linear polarisation DoLP = sqrt(S1^2 + S2^2) /
// S0 and its angle AoLP = atan2(S2, S1) / 2 (degrees counter-clockwise from the image's right),
// which means something only where the light is polarised: the AoLP figure masks pixels whose
// DoLP is below `dolpThreshold`. DoLP of a noisy pixel is biased upwards (a norm of noisy S1,
// S2), which the polarised render's twin bounds: its mean DoLP difference is reported too.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// The AoLP figure's mask by default: light less than 5% linearly polarised has no angle worth
/// drawing (its AoLP is mostly the noise of S1 and S2).
inline constexpr double kDefaultDolpThreshold = 0.05;

struct PolarisationInputs {
    std::string scene;
    int spp = 0;                      ///< of every render; 0: the scene's
    render::RenderOptions overrides;  ///< --resolution, --threads, --max-depth, --seed
    double dolpThreshold = kDefaultDolpThreshold;
    ProgressSink progress;
    /// Where the renders are kept as they finish (empty: nowhere), and whether those already
    /// there are taken back (kept_renders.h).
    std::filesystem::path keepDirectory;
    bool resume = false;
};

/// An unpolarised mode's render of the scene against the polarised one.
struct AgainstPolarised {
    render::RenderResult render;
    ImageMetrics metrics;  ///< against the polarised render (the reference)
    /// Per pixel, row-major from the top row. `relative`: NaN where both renders are black.
    std::vector<float> relative, ciede2000;
    FlooredStatistic meanRelative, p95Relative, meanDeltaE, p95DeltaE;
    std::size_t comparedPixels = 0;  ///< pixels not black in both renders (`relative`'s)
};

struct PolarisationResult {
    std::string scene;
    double dolpThreshold = kDefaultDolpThreshold;
    render::RenderResult polarised;
    /// The spectral mode (s and p averaged at each event: polarisation alone differs) and the
    /// RGB mode (also its colour and Fresnel approximations: F82 for metals, the d-line index).
    AgainstPolarised spectral, rgb;
    int width = 0, height = 0;
    /// The pixels with light in the polarised render: S0 above 1e-6 of the brightest pixel's
    /// (a light that cancels to float rounding, crossed mirrors at Brewster's angle, is none).
    std::vector<bool> lit;
    /// The polarised render's DoLP and AoLP in degrees, 0 where there is no light.
    std::vector<float> dolp, aolp;
    double meanDolp = 0, maxDolp = 0;  ///< over the lit pixels
    /// The mean |DoLP - DoLP of the twin render| over the lit pixels: DoLP's noise.
    double dolpNoise = 0;
};

PolarisationResult runPolarisation(const PolarisationInputs& inputs);

/// The renders (EXR: the polarised one with its Stokes layers), the difference, CIEDE2000,
/// DoLP and AoLP figures, and summary.md.
void writePolarisationReport(const PolarisationResult& result, Report& report);

}  // namespace lamina::experiments
