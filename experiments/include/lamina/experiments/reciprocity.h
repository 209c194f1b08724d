// Do camera tracing, light tracing and BDPT converge to the same image (`lamina reciprocity`)?
// Each integrator renders the scene as independent batches with its own seeds
// (estimator_agreement.h); every pair (and each against a reference image, if given) is tested
// per pixel and per block; the BSDF of every material is checked for reciprocity and for the
// adjoint identity in both modes (bsdf_reciprocity.h). The report is a running log on the
// console and, per integrator and per pair, the mean image and the t-statistic maps. The batch
// renders are kept in the report's directory as they finish and taken back by a resumed run
// (kept_renders.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/experiments/bsdf_reciprocity.h"
#include "lamina/experiments/estimator_agreement.h"
#include "lamina/experiments/progress.h"
#include "lamina/experiments/report.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// A known bug reproduced on purpose, to show that the test catches it.
enum class Ablation {
    AdjointCorrection,  ///< drop the shading-normal factor on light paths
    TransportMode,      ///< radiance's 1/eta^2 on light paths
    SwappedDirections,  ///< f(wi, wo) at light-path connections
};
inline constexpr NameTable kAblationNames{
    std::array{NameEntry{Ablation::AdjointCorrection, "adjoint-correction"},
               NameEntry{Ablation::TransportMode, "transport-mode"},
               NameEntry{Ablation::SwappedDirections, "swapped-directions"}}};

struct ReciprocityInputs {
    std::string scene;  ///< scene file
    /// Every integrator of kIntegratorNames unless chosen.
    std::vector<render::IntegratorKind> integrators = render::kIntegratorNames.values();
    render::RenderModeKind mode = render::RenderModeKind::Rgb;
    int spp = 256;           ///< per integrator, over all batches
    int batches = 16;        ///< independent batches per integrator
    std::uint64_t seed = 0;  ///< base seed; each integrator's is derived from it
    AgreementTest test;      ///< significance level and block size
    std::string reference;   ///< optional: each integrator is also tested against this EXR
    std::vector<Ablation> ablations;
    /// Applied to every render (threads, max depth, resolution); the mode, the integrator
    /// and the seed are set per render.
    render::RenderOptions overrides;
    ProgressSink progress;
    /// Where every batch render is kept as it finishes (empty: nowhere), and whether those
    /// already there are taken back (kept_renders.h).
    std::filesystem::path keepDirectory;
    bool resume = false;
};

struct IntegratorBatches {
    render::IntegratorKind integrator;
    BatchImages images;
    double seconds = 0;
};

struct PairAgreement {
    std::string nameA, nameB;  ///< integrator names, or "reference"
    AgreementResult result;
    bool agree = false;
    PixelTestCalibration pixelTest;  ///< whether its per-pixel rejection rate means anything
    int width = 0, height = 0;       ///< of the t-statistic maps
};

struct MaterialReciprocity {
    std::string material;
    render::RenderModeKind mode;
    BsdfReciprocity check;
};

struct ReciprocityResult {
    ReciprocityInputs inputs;
    std::vector<IntegratorBatches> renders;
    std::vector<PairAgreement> pairs;
    std::vector<MaterialReciprocity> materials;  ///< every material in RGB, then in spectral mode
    /// The pair whose per-pixel test is the least trustworthy (the verdict reports it).
    PixelTestCalibration pixelTest;
    bool allAgree = true;
};

/// Direction pairs of each material's BSDF check.
inline constexpr int kBsdfReciprocityPairs = 20000;

ReciprocityResult runReciprocity(const ReciprocityInputs& inputs);

/// The log on the console (the pairs' verdicts, the BSDF table, the overall verdict); per
/// integrator INTEGRATOR.exr (the mean image), per pair t_A_vs_B.exr and its two heat maps.
void writeReciprocityReport(const ReciprocityResult& result, Report& report);

}  // namespace lamina::experiments
