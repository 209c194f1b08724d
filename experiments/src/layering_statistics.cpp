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

TwinComparison compareWithWalk(const MeanEstimate& twin, const MeanEstimate& walk) {
    TwinComparison c;
    const double difference = twin.mean - walk.mean;
    if (!(std::abs(walk.mean) >= kAbsoluteFloor)) {
        c.absolute = true;
        c.error = difference / kAbsoluteFloor;
        c.standardError = std::hypot(twin.standardError, walk.standardError) / kAbsoluteFloor;
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
