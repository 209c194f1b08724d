// The polarised case of `lamina stability`: a model's Mueller matrices (evalMueller and
// sampleMueller, docs/polarisation.md) in float and double, at the directions where the Fresnel
// amplitudes or the frames are singular or degenerate:
//   - wo along the normal (every plane contains it: the s axis is a convention) with wi along
//     +-z and mirrored, and wo at cos(theta) = +-1e-8 and 0 (grazing: r_s = r_p = -1);
//   - Brewster's angle atan(eta) of each side of an interface (r_p = 0, M22 changes sign);
//   - the critical angle asin(eta) of the dense side (eta < 1: the onset of total internal
//     reflection, where cos(theta_t) has a square-root singularity);
// each probed at cos(theta) and one ulp of the precision below and above it (along the normal,
// one ulp off it: the plane of incidence turns from stokesAxis's convention to xz), wo in the xz
// plane, on the reflection (the mirror direction: the half vector is the normal) and, for a
// transmissive model, the refraction direction; for a model whose lobes are delta, through
// sample() with the random numbers at the edges of [0, 1) (reflection and refraction).
// Counted: NaN and Inf in any element of any channel; and the jump, the largest change of an
// element of the matrix normalised by its own [0][0] (and of [0][0] relative to itself) between
// the centre and each neighbour one ulp away, over the largest [0][0] there. A continuous
// function moves by O(ulp) there and by O(sqrt(ulp)) at the critical angle's square-root
// singularity: kPolarisedJumpBound.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lamina/bsdf/material_builder.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina::experiments {

/// The largest jump the audit accepts, per precision: 64 sqrt(epsilon). A continuous function
/// moves by O(ulp) between neighbours, and by C sqrt(ulp) at the critical angle's square-root
/// singularity, C growing with the index (about 14 for a rough interface of index 4, the
/// steepest of the default set); a sign or branch error (r_p's sign, cos(theta_t) on the
/// growing wave's branch, a frame turned the wrong way) moves an element by O(1).
template <typename T>
inline constexpr double kPolarisedJumpBound = 64 * 3.4526698e-4;  // float: 64 sqrt(2^-23)
template <>
inline constexpr double kPolarisedJumpBound<double> = 64 * 1.4901161e-8;  // 64 sqrt(2^-52)

/// One probed configuration.
struct PolarisedProbe {
    std::string what;                      ///< "Brewster's angle, outside", ...
    double cosTheta = 0;                   ///< of wo (negative: inside)
    double alpha = 0;                      ///< the model's roughness (0: smooth)
    int evaluations = 0;                   ///< matrices computed, both precisions
    int nan = 0, inf = 0;                  ///< matrices with a NaN or Inf element
    double jumpFloat = 0, jumpDouble = 0;  ///< across +-1 ulp; 0 where not probed
};

struct PolarisedStabilityReport {
    std::vector<PolarisedProbe> probes;
    int evaluations = 0, nan = 0, inf = 0;
    double worstJumpFloat = 0, worstJumpDouble = 0;
    /// Probes whose jump exceeds kPolarisedJumpBound of their precision.
    int discontinuities = 0;
    int issues() const { return nan + inf + discontinuities; }
};

/// The relative indices (transmitted over incident side, from outside) whose Brewster and
/// critical angles are probed: a dielectric's `ior` or a reflection-only conductor's `eta` with
/// k = 0, when a number (none for other models: only the normal and grazing probes).
std::vector<double> probedIndices(const std::string& materialJson);

/// Builds the model at a given alpha in both precisions, at the wavelengths given (which the
/// model may keep a reference to: they outlive it).
struct PolarisedStabilityModel {
    std::function<std::unique_ptr<Bxdf<SampledSpectrum<double>>>(
        double alpha, SampledWavelengths<double>& lambda)>
        makeDouble;
    std::function<std::unique_ptr<Bxdf<SampledSpectrum<float>>>(double alpha,
                                                                SampledWavelengths<float>& lambda)>
        makeFloat;
};

/// The audit of a model at each of `alphas`, at 450, 520, 600 and 680 nm, with the Brewster
/// and critical angles of `indices` (probedIndices).
PolarisedStabilityReport auditPolarisedStability(const PolarisedStabilityModel& model,
                                                 const std::vector<double>& alphas,
                                                 const std::vector<double>& indices);

/// The same for a material, `materialAt(alpha)` (its spectral build).
PolarisedStabilityReport auditPolarisedStability(
    const std::function<MaterialDesc(double alpha)>& materialAt, const std::vector<double>& alphas,
    const std::vector<double>& indices);

}  // namespace lamina::experiments
