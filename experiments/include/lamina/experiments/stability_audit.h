// The numerical-stability audit of a BSDF model (lamina stability): over a grid of roughness
// (alpha) and viewing angle, the model built in double and in float is evaluated on a fixed
// set of directions (random ones plus the special cases: wo itself, its mirror image, -wo,
// the horizon) in both transport modes and sampled with random numbers including the edges of
// [0, 1). Counted per cell:
//   nan, inf, negative     eval, pdf or a sample's weight (either precision)
//   weightMismatch         a non-delta sample whose weight differs from eval / pdf by more
//                          than 1e-3 relative (double precision)
//   energyGain             the mean sample weight in importance mode (the directional albedo:
//                          radiance mode's 1/eta^2 is not energy) exceeds 1 by more than
//                          three standard errors plus 1e-3, in some channel
// and the worst relative difference between float and double eval where the double value is
// above 1e-6 of the cell's peak (ill-conditioned points included: near the critical angle a
// one-ulp change of direction changes rough refraction by ~1%).
// Samples alternate between the two transport modes; eval / pdf is checked in the mode drawn.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

#include "lamina/bsdf/bxdf.h"

namespace lamina::experiments {

struct StabilityCell {
    int evaluations = 0, samples = 0;
    int nan = 0, inf = 0, negative = 0, weightMismatch = 0, energyGain = 0;
    double worstFloatError = 0;
    int issues() const { return nan + inf + negative + weightMismatch + energyGain; }
};

struct StabilityReport {
    std::vector<double> alphas, cosines;
    std::vector<StabilityCell> cells;  ///< alphas.size() x cosines.size(), alpha-major
    const StabilityCell& at(std::size_t a, std::size_t c) const {
        return cells[a * cosines.size() + c];
    }
    StabilityCell total() const {
        StabilityCell t;
        for (const StabilityCell& c : cells) {
            t.evaluations += c.evaluations;
            t.samples += c.samples;
            t.nan += c.nan;
            t.inf += c.inf;
            t.negative += c.negative;
            t.weightMismatch += c.weightMismatch;
            t.energyGain += c.energyGain;
            t.worstFloatError = std::max(t.worstFloatError, c.worstFloatError);
        }
        return t;
    }
};

/// Builds the model at a given alpha, in both precisions.
struct StabilityModel {
    std::function<std::unique_ptr<Bxdf<Rgb<double>>>(double alpha)> makeDouble;
    std::function<std::unique_ptr<Bxdf<Rgb<float>>>(double alpha)> makeFloat;
};

/// The audit over the grid alphas x cosines (`directions` random evaluation directions and
/// `samples` samples per cell).
StabilityReport auditStability(const StabilityModel& model, std::vector<double> alphas,
                               std::vector<double> cosines, int directions = 64,
                               int samples = 4096);

}  // namespace lamina::experiments
