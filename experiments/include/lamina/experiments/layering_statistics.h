// The statistics of `lamina layering`. The random walk of a `coated` material is itself an
// estimate, so every number taken from it is a mean of independent estimates with its standard
// error, and a difference from an analytic twin is classified against the tolerance bands (1%,
// 5%, 20%) only as far as its error bar allows: "within 1%" needs the whole error bar inside
// 1%, "beyond 20%" needs it wholly outside 20%, and anything in between is "not resolved at
// this sample count".
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "lamina/core/name_table.h"

namespace lamina::experiments {

/// A mean of independent estimates and its standard error (sample standard deviation /
/// sqrt(count); 0 for fewer than two estimates).
struct MeanEstimate {
    double mean = 0;
    double standardError = 0;
    std::int64_t count = 0;
};

/// One-pass mean and variance (Welford 1962, "Note on a method for calculating corrected sums
/// of squares and products": the update that does not lose precision to cancellation).
class RunningMean {
  public:
    void add(double x) {
        ++n_;
        const double d = x - mean_;
        mean_ += d / double(n_);
        m2_ += d * (x - mean_);
    }
    MeanEstimate estimate() const;

  private:
    std::int64_t n_ = 0;
    double mean_ = 0, m2_ = 0;
};

/// The tolerance bands of the summary, as fractions.
inline constexpr std::array<double, 3> kToleranceBands = {0.01, 0.05, 0.20};
/// An error bar spans this many standard errors on each side (about 95% for a normal mean).
inline constexpr double kErrorBarWidth = 2.0;
/// Where the walk's value (an albedo, or f |cos| in 1/sr) is below this, a relative error would
/// divide by almost nothing: the error is measured against this floor instead (an absolute
/// error in units of the floor). A fixed floor, not a fraction of a figure's largest value: a
/// peaked lobe's largest value would hide every error of its diffuse part.
inline constexpr double kAbsoluteFloor = 1e-4;

/// The smallest tolerance band the error bar establishes, or why there is none.
enum class Agreement { Within1, Within5, Within20, Beyond20, Unresolved };
inline constexpr NameTable kAgreementNames{std::array{
    NameEntry{Agreement::Within1, "within 1%"}, NameEntry{Agreement::Within5, "within 5%"},
    NameEntry{Agreement::Within20, "within 20%"}, NameEntry{Agreement::Beyond20, "beyond 20%"},
    NameEntry{Agreement::Unresolved, "not resolved at this sample count"}}};

/// A twin's value against the walk's at one point.
struct TwinComparison {
    double error = 0;          ///< (twin - walk) / walk, or / kAbsoluteFloor where `absolute`
    double standardError = 0;  ///< of `error`
    bool absolute = false;     ///< the walk's value is below kAbsoluteFloor
    Agreement agreement = Agreement::Unresolved;

    /// Whether the error bar lies wholly inside the band, wholly outside it, or neither.
    bool within(double band) const {
        return std::abs(error) + kErrorBarWidth * standardError <= band;
    }
    bool beyond(double band) const {
        return std::abs(error) - kErrorBarWidth * standardError > band;
    }
};

/// Compares a twin's estimate with the walk's. The standard error of the relative error is the
/// first-order (delta method) one of the ratio: sqrt(se_twin^2 + (twin / walk)^2 se_walk^2) /
/// |walk|.
TwinComparison compareWithWalk(const MeanEstimate& twin, const MeanEstimate& walk);

/// How many points of a set fall inside, outside and undecided for each band.
struct BandCounts {
    std::array<int, 3> within{}, beyond{}, unresolved{};
    int points = 0, absolute = 0;
    void add(const TwinComparison& c);
};

}  // namespace lamina::experiments
