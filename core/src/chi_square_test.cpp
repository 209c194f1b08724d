#include "lamina/core/chi_square_test.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "lamina/core/incomplete_gamma.h"
#include "lamina/core/math.h"

namespace lamina {
namespace {

// Maps histogram coordinates (x, y) to a point of the domain.
Vec3d domainPoint(ChiSquareDomain domain, double x, double y) {
    if (domain == ChiSquareDomain::Plane) return {x, y, 0.0};
    const double sinTheta = safeSqrt(1.0 - y * y);
    return {sinTheta * std::cos(x), sinTheta * std::sin(x), y};
}

struct Grid {
    Vec2d lo, hi;
    int nx, ny;
    double cellWidth() const { return (hi.x - lo.x) / nx; }
    double cellHeight() const { return (hi.y - lo.y) / ny; }
};

Grid makeGrid(const ChiSquareConfig& c) {
    if (c.domain == ChiSquareDomain::Plane)
        return {c.planeMin, c.planeMax, c.phiBins, c.cosThetaBins};
    return {{0.0, -1.0}, {2.0 * kPi<double>, 1.0}, c.phiBins, c.cosThetaBins};
}

// Histogram coordinates of a sample, or nullopt if it lies outside the grid.
std::optional<std::pair<int, int>> cellOf(const Grid& g, ChiSquareDomain domain, const Vec3d& p) {
    double x, y;
    if (domain == ChiSquareDomain::Plane) {
        x = p.x;
        y = p.y;
    } else {
        x = std::atan2(p.y, p.x);
        if (x < 0.0) x += 2.0 * kPi<double>;
        y = p.z;
    }
    auto ix = static_cast<int>(std::floor((x - g.lo.x) / (g.hi.x - g.lo.x) * g.nx));
    auto iy = static_cast<int>(std::floor((y - g.lo.y) / (g.hi.y - g.lo.y) * g.ny));
    if (domain == ChiSquareDomain::Sphere) {  // the closed ends phi = 2 pi, cos = 1 belong inside
        ix = std::clamp(ix, 0, g.nx - 1);
        iy = std::clamp(iy, 0, g.ny - 1);
    }
    if (ix < 0 || iy < 0 || ix >= g.nx || iy >= g.ny) return std::nullopt;
    return std::make_pair(ix, iy);
}

// 3-point Gauss-Legendre rule on a rectangle (nodes strictly inside, so a density that jumps
// on a cell edge is never sampled on the wrong side of the jump).
double gauss3(ChiSquareDomain domain, double x0, double y0, double w, double h,
              const ChiSquarePdf& pdf) {
    static constexpr double kNode[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static constexpr double kWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double sum = 0.0;
    for (int j = 0; j < 3; ++j) {
        const double y = y0 + 0.5 * h * (1.0 + kNode[j]);
        for (int i = 0; i < 3; ++i) {
            const double value = pdf(domainPoint(domain, x0 + 0.5 * w * (1.0 + kNode[i]), y));
            if (std::isfinite(value)) sum += kWeight[i] * kWeight[j] * value;
        }
    }
    return sum * 0.25 * w * h;
}

// Adaptive quadrature: a rectangle is split in four until the split changes the integral by
// less than a relative 1e-4, so densities with jumps inside a cell (a cone's rim, a
// triangle's edge) and narrow peaks (smooth microfacet lobes) are still integrated accurately.
double integrateAdaptive(ChiSquareDomain domain, double x0, double y0, double w, double h,
                         double coarse, int depth, int minDepth, const ChiSquarePdf& pdf) {
    const double hw = 0.5 * w, hh = 0.5 * h;
    const double q[4] = {
        gauss3(domain, x0, y0, hw, hh, pdf), gauss3(domain, x0 + hw, y0, hw, hh, pdf),
        gauss3(domain, x0, y0 + hh, hw, hh, pdf), gauss3(domain, x0 + hw, y0 + hh, hw, hh, pdf)};
    const double fine = q[0] + q[1] + q[2] + q[3];
    // The first levels are always refined (12 x 12 nodes per cell) so that a density that is
    // non-zero only in a corner of a cell is not missed by the coarse rule.
    const bool converged = std::abs(fine - coarse) <= 1e-4 * std::abs(fine) + 1e-14;
    if (depth <= 0 || (converged && depth <= minDepth)) return fine;
    return integrateAdaptive(domain, x0, y0, hw, hh, q[0], depth - 1, minDepth, pdf) +
           integrateAdaptive(domain, x0 + hw, y0, hw, hh, q[1], depth - 1, minDepth, pdf) +
           integrateAdaptive(domain, x0, y0 + hh, hw, hh, q[2], depth - 1, minDepth, pdf) +
           integrateAdaptive(domain, x0 + hw, y0 + hh, hw, hh, q[3], depth - 1, minDepth, pdf);
}

double integrateCell(const Grid& g, ChiSquareDomain domain, int ix, int iy, int maxDepth,
                     const ChiSquarePdf& pdf) {
    const double w = g.cellWidth(), h = g.cellHeight();
    const double x0 = g.lo.x + ix * w, y0 = g.lo.y + iy * h;
    return integrateAdaptive(domain, x0, y0, w, h, gauss3(domain, x0, y0, w, h, pdf), maxDepth,
                             maxDepth - 2, pdf);
}

}  // namespace

double sidakCorrectedAlpha(double alpha, int testCount) {
    return 1.0 - std::pow(1.0 - alpha, 1.0 / std::max(1, testCount));
}

bool pearsonStatistic(std::size_t sampleCount, ChiSquareResult& result) {
    // Pool cells with an expected count below 5 (Pearson's statistic is only chi-square
    // distributed when every expected count is reasonably large).
    const std::size_t cells = result.expected.size();
    std::vector<std::size_t> order(cells);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return result.expected[a] < result.expected[b];
    });
    constexpr double kMinExpected = 5.0;
    double pooledExpected = 0.0, pooledObserved = 0.0, statistic = 0.0;
    int bins = 0;
    for (std::size_t idx : order) {
        const double e = result.expected[idx], o = result.observed[idx];
        if (e == 0.0 && o > static_cast<double>(sampleCount) * 1e-5) {
            std::ostringstream msg;
            msg << o << " samples fell in cell " << idx << " where the density is 0";
            result.message = msg.str();
            return false;
        }
        if (e < kMinExpected) {
            pooledExpected += e;
            pooledObserved += o;
        } else if (pooledExpected > 0.0 && pooledExpected < kMinExpected) {
            // Fold a still-too-small pool into the smallest regular cell.
            statistic += sqr(o + pooledObserved - e - pooledExpected) / (e + pooledExpected);
            pooledExpected = pooledObserved = 0.0;
            ++bins;
        } else {
            statistic += sqr(o - e) / e;
            ++bins;
        }
    }
    if (pooledExpected >= kMinExpected) {
        statistic += sqr(pooledObserved - pooledExpected) / pooledExpected;
        ++bins;
    }
    result.statistic = statistic;
    result.degreesOfFreedom = bins - 1;
    if (result.degreesOfFreedom < 1) {
        result.message = "too few populated cells for a chi-square test";
        return false;
    }
    result.pValue = chiSquarePValue(statistic, result.degreesOfFreedom);
    result.passed = result.pValue >= result.alpha;
    return true;
}

ChiSquareResult runChiSquareTest(const ChiSquareConfig& config, const ChiSquareSampler& sampler,
                                 const ChiSquarePdf& pdf) {
    ChiSquareResult result;
    result.alpha = sidakCorrectedAlpha(config.significance, config.testCount);
    const Grid grid = makeGrid(config);
    const std::size_t cells = static_cast<std::size_t>(grid.nx) * grid.ny;
    result.observed.assign(cells, 0.0);
    result.expected.assign(cells, 0.0);

    // 1. Histogram of samples.
    Pcg32 rng(config.seed, 0x5eed);
    for (std::size_t i = 0; i < config.sampleCount; ++i) {
        const std::optional<Vec3d> s = sampler(rng);
        if (!s) continue;
        if (!isFinite(*s)) {
            result.message = "the sampler returned a non-finite point";
            return result;
        }
        if (config.domain == ChiSquareDomain::Sphere && std::abs(glm::length(*s) - 1.0) > 1e-3) {
            result.message = "the sampler returned a direction that is not unit length";
            return result;
        }
        const auto cell = cellOf(grid, config.domain, *s);
        if (!cell) {
            result.message = "the sampler returned a point outside the test domain";
            return result;
        }
        result.observed[static_cast<std::size_t>(cell->second) * grid.nx + cell->first] += 1.0;
        ++result.validSamples;
    }

    // 2. Expected counts from the density.
    double integral = 0.0;
    for (int iy = 0; iy < grid.ny; ++iy) {
        for (int ix = 0; ix < grid.nx; ++ix) {
            const double p =
                integrateCell(grid, config.domain, ix, iy, config.maxSubdivisions, pdf);
            integral += p;
            result.expected[static_cast<std::size_t>(iy) * grid.nx + ix] =
                p * static_cast<double>(config.sampleCount);
        }
    }
    result.pdfIntegral = integral;
    if (integral > 1.0 + 1e-2) {
        std::ostringstream msg;
        msg << "the density integrates to " << integral << " > 1 over the domain";
        result.message = msg.str();
        return result;
    }

    // 3. Pearson's statistic over the cells.
    if (!pearsonStatistic(config.sampleCount, result)) return result;
    std::ostringstream msg;
    msg << "chi2 = " << result.statistic << " with " << result.degreesOfFreedom
        << " degrees of freedom, p = " << result.pValue << " (alpha = " << result.alpha << ", "
        << (result.passed ? "accepted" : "rejected") << "), " << result.validSamples << " of "
        << config.sampleCount << " samples valid, density integral " << integral;
    result.message = msg.str();
    return result;
}

}  // namespace lamina
