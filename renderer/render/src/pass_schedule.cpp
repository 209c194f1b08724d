#include "lamina/render/pass_schedule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lamina::render {

namespace {
constexpr int kMaxPassSpp = 64;
}

PassSchedule::PassSchedule(int targetSpp, std::optional<double> seconds)
    : targetSpp_(seconds ? std::numeric_limits<int>::max() : targetSpp), seconds_(seconds) {}

int PassSchedule::next(int done, double elapsed) const {
    if (done >= targetSpp_) return 0;
    int spp = std::min(targetSpp_ - done, std::max(1, std::min(done, kMaxPassSpp)));
    if (!seconds_ || done == 0) return spp;  // a render has at least one sample per pixel
    const double remaining = *seconds_ - elapsed;
    if (!(remaining > 0)) return 0;
    if (measuredSpp_ > 0 && measuredSeconds_ > 0) {
        // The rate over every pass so far (the first, small passes alone are noisy).
        const double secondsPerSpp = measuredSeconds_ / measuredSpp_;
        const double fit = std::floor(remaining / secondsPerSpp + 0.5);
        if (fit < 1) return 0;
        spp = int(std::min<double>(spp, fit));
    }
    return spp;
}

void PassSchedule::record(int spp, double seconds) {
    measuredSpp_ += spp;
    measuredSeconds_ += seconds;
}

}  // namespace lamina::render
