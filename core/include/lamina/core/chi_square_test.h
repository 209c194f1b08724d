// Chi-square goodness-of-fit test for samplers that come with a density, in the manner of
// Mitsuba 3's BSDF tests: draw many samples into a histogram, integrate the density over each
// histogram cell by adaptive Gauss-Legendre quadrature to get the expected counts, pool cells whose
// expected count is below 5, and compare with Pearson's statistic. A sampler passes when the
// p-value is above the significance level after a Sidak correction for the number of tests in the
// suite.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/pcg32.h"
#include "lamina/core/vector.h"

namespace lamina {

/// The domain the histogram covers.
enum class ChiSquareDomain {
    /// Unit directions; cells are a (phi, cos theta) grid over [0, 2 pi) x [-1, 1]. The
    /// Jacobian of that parameterisation is 1, so a solid-angle density integrates directly.
    Sphere,
    /// Points (x, y) of the plane; cells are a grid over [planeMin, planeMax]. The density is
    /// per unit area.
    Plane,
};

struct ChiSquareConfig {
    ChiSquareDomain domain = ChiSquareDomain::Sphere;
    int cosThetaBins = 32;  ///< y resolution (cos theta, or plane y)
    int phiBins = 64;       ///< x resolution (phi, or plane x)
    std::size_t sampleCount = 1000000;
    int maxSubdivisions = 7;     ///< depth of the adaptive quadrature of the density per cell
    double significance = 0.01;  ///< family-wise significance level of the suite
    int testCount = 1;           ///< number of tests in the suite (Sidak correction)
    std::uint64_t seed = 7;
    Vec2d planeMin{-1.0, -1.0};
    Vec2d planeMax{1.0, 1.0};
};

struct ChiSquareResult {
    bool passed = false;
    double pValue = 0.0;
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double alpha = 0.0;            ///< per-test significance after the Sidak correction
    std::size_t validSamples = 0;  ///< samples the sampler returned (others failed)
    double pdfIntegral = 0.0;      ///< integral of the density over the domain
    std::string message;           ///< why it failed, or a one-line summary

    std::vector<double> observed;  ///< per cell, row-major (cos theta / y rows)
    std::vector<double> expected;
};

/// Draws a sample from the random stream; nullopt when the sampler fails (absorbed sample).
using ChiSquareSampler = std::function<std::optional<Vec3d>(Pcg32&)>;
/// The density of the sampler at a direction (Sphere) or a point (Plane, z ignored).
using ChiSquarePdf = std::function<double(const Vec3d&)>;

/// Per-test significance that keeps the family-wise level at `alpha` over `testCount` tests.
double sidakCorrectedAlpha(double alpha, int testCount);

/// Pearson's test of result.observed against result.expected (counts of `sampleCount` draws;
/// cells expected below 5 pooled) at result.alpha: fills statistic, degreesOfFreedom, pValue
/// and passed; false, with the reason in message, when the counts cannot be tested (samples
/// where nothing was expected, too few cells).
bool pearsonStatistic(std::size_t sampleCount, ChiSquareResult& result);

ChiSquareResult runChiSquareTest(const ChiSquareConfig& config, const ChiSquareSampler& sampler,
                                 const ChiSquarePdf& pdf);

}  // namespace lamina
