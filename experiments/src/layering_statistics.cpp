#include "lamina/experiments/layering_statistics.h"

#include <cmath>

namespace lamina::experiments {

MeanEstimate RunningMean::estimate() const {
    MeanEstimate e;
    e.mean = mean_;
    e.count = n_;
    if (n_ > 1) e.standardError = std::sqrt(m2_ / double(n_ - 1) / double(n_));
    return e;
}

TwinComparison compareWithWalk(const MeanEstimate& twin, const MeanEstimate& walk, double scale) {
    TwinComparison c;
    const double floor = kAbsoluteFloor * std::abs(scale);
    const double difference = twin.mean - walk.mean;
    if (!(std::abs(walk.mean) > floor) || !(std::abs(walk.mean) > 0)) {
        c.absolute = true;
        // A scale of 0 (everything black): the difference itself, on the scale of 1.
        const double s = std::abs(scale) > 0 ? std::abs(scale) : 1.0;
        c.error = difference / s;
        c.standardError = std::hypot(twin.standardError, walk.standardError) / s;
    } else {
        const double ratio = twin.mean / walk.mean;
        c.error = difference / walk.mean;
        c.standardError =
            std::hypot(twin.standardError, ratio * walk.standardError) / std::abs(walk.mean);
    }
    if (c.within(kToleranceBands[0]))
        c.agreement = Agreement::Within1;
    else if (c.within(kToleranceBands[1]))
        c.agreement = Agreement::Within5;
    else if (c.within(kToleranceBands[2]))
        c.agreement = Agreement::Within20;
    else if (c.beyond(kToleranceBands[2]))
        c.agreement = Agreement::Beyond20;
    else
        c.agreement = Agreement::Unresolved;
    return c;
}

void BandCounts::add(const TwinComparison& c) {
    ++points;
    if (c.absolute) ++absolute;
    for (std::size_t b = 0; b < kToleranceBands.size(); ++b) {
        if (c.within(kToleranceBands[b]))
            ++within[b];
        else if (c.beyond(kToleranceBands[b]))
            ++beyond[b];
        else
            ++unresolved[b];
    }
}

}  // namespace lamina::experiments
