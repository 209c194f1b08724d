// How far RGB mode's Fresnel models are from the exact spectral Fresnel reflectance of
// measured conductors and dispersive dielectrics (`lamina fresnel`).
//
// For each material, at every angle from 0 to 89 degrees (and 90, where all are 1):
//  - exact: the Fresnel equations per wavelength (complex index n + ik; 380-780 nm), and its
//    colour under D65 in linear Rec.709 (what a spectral render of a white-lit flat surface
//    shows);
//  - RGB models, built from that exact colour the way RGB mode builds them: Schlick from F0
//    (F90 = 1), Schlick with shadowed F90 = min(1, luminance(F0) / 0.04), Hoffman's F82 (F0
//    and the exact colour at cos = 1/7), Lagarde's spherical-Gaussian Schlick, and for
//    dielectrics the exact equations at the d-line index (RGB mode's dielectric).
// With a thin film (thickness > 0), every material carries that film (docs/bsdf.md, "Thin
// films"): the exact reflectance is the Airy sum per wavelength, and the RGB models are RGB
// mode's film (Belcour and Barla's closed form, with the channels' indices) and, for scale,
// Hoffman's F82 of the bare material (what RGB mode gives a metal that ignores the film).
// Reported per model: the maximum and mean absolute error of the RGB reflectance and the
// maximum and mean CIEDE2000 difference of its colour (as a reflectance under D65). Written:
// MATERIAL.csv (the RGB curves), MATERIAL_spectral.csv (one column per 20 nm),
// the figures (figure_spec.h) MATERIAL.png/.pdf (each model's reflectance against angle, one
// panel per channel) and MATERIAL_swatches.png/.pdf (rows: exact, models; columns: 0, 30, 60,
// 75, 82, 87 degrees), summary.md. With a scene, renders it in both modes with the same seed
// and writes the difference and a CIEDE2000 map (scene_ciede2000.png/.pdf), and renders both
// modes once more with another seed: the two pairs give the noise of the modes' difference, the
// floor every difference is read against (pairedNoise, noise_floor.h). The scene's renders
// are kept in the report's directory as they finish and taken back by a resumed run
// (kept_renders.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/spectrum.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

inline constexpr int kFresnelAngles = 91;  ///< 0, 1, ..., 90 degrees

struct FresnelInputs {
    /// Metals (Au, Ag, ...), glasses (bk7, diamond, ...) or n/k files (YAML or CSV).
    std::vector<std::string> materials;
    double thinFilmNm = 0;            ///< a film on every material; 0: none
    double thinFilmIor = 1.33;        ///< the film's index
    std::string scene;                ///< optional: also rendered in both modes and compared
    int spp = 0;                      ///< of the scene renders; 0: the scene's
    render::RenderOptions overrides;  ///< --resolution, --threads, --max-depth of the scene renders
    ProgressSink progress;
    /// Where the scene's renders are kept as they finish (empty: nowhere), and whether those
    /// already there are taken back (kept_renders.h).
    std::filesystem::path keepDirectory;
    bool resume = false;
};

/// One model's reflectance against angle and its error against the exact colour.
struct FresnelModel {
    std::string name;
    std::vector<Rgb<double>> rgb;  ///< per angle
    double maxError = 0, meanError = 0, maxDeltaE = 0, meanDeltaE = 0;
};

/// The exact reflectance at one wavelength against angle.
struct WavelengthCurve {
    double nm;
    std::vector<double> reflectance;  ///< per angle
};

struct FresnelMaterial {
    std::string stem;                  ///< the argument's file-name stem: the report's file names
    std::string name;                  ///< the n/k data's own name (plot titles)
    std::vector<FresnelModel> models;  ///< the exact colour first, then the RGB models
    std::vector<WavelengthCurve> spectral;  ///< 380, 400, ..., 780 nm
    std::vector<WavelengthCurve> plotted;   ///< 450, 550 and 650 nm
};

/// The scene rendered in RGB and in spectral mode.
struct FresnelSceneComparison {
    std::string scene;
    render::RenderResult rgb, spectral;
    ImageMetrics metrics;          ///< RGB against spectral
    std::vector<float> ciede2000;  ///< per pixel
    double meanDeltaE = 0, maxDeltaE = 0, p95DeltaE = 0;
    /// The noise floor, its mean and 95th percentile: the CIEDE2000 between two images that
    /// differ by the noise of the modes' difference alone, measured from the second pair
    /// (pairedNoise).
    double floorMeanDeltaE = 0, floorP95DeltaE = 0;
    /// The mean and 95th percentile CIEDE2000 between the two modes' renders of the second seed.
    double otherSeedMeanDeltaE = 0, otherSeedP95DeltaE = 0;
};

struct FresnelResult {
    std::vector<FresnelMaterial> materials;
    double thinFilmNm = 0, thinFilmIor = 1.33;  ///< the film on every material (0: none)
    std::optional<FresnelSceneComparison> scene;
};

FresnelResult runFresnel(const FresnelInputs& inputs);

/// Per material its CSVs, plot and swatches; the scene's images; the summary.
void writeFresnelReport(const FresnelResult& result, Report& report);

}  // namespace lamina::experiments
