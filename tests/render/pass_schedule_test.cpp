// The pass schedule: passes double up to 64 spp; with a time budget they follow the measured
// rate so the render ends within half a sample per pixel of the budget (tested here with
// synthetic timings: deterministic, unlike a wall-clock test on a shared machine).
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/render/pass_schedule.h"

namespace lamina::render {
namespace {

// Runs a schedule against a clock where every sample per pixel costs `secondsPerSpp`, after
// `startup` seconds (scene loading, the BVH). Returns {spp done, seconds at the end}.
std::pair<int, double> simulate(PassSchedule& schedule, double secondsPerSpp, double startup,
                                std::vector<int>* passes = nullptr) {
    int done = 0;
    double t = startup;
    while (const int spp = schedule.next(done, t)) {
        t += spp * secondsPerSpp;
        schedule.record(spp, spp * secondsPerSpp);
        done += spp;
        if (passes) passes->push_back(spp);
    }
    return {done, t};
}

TEST(PassSchedule, PassesDoubleUpTo64AndEndAtTheTarget) {
    PassSchedule schedule(300, std::nullopt);
    std::vector<int> passes;
    const auto [spp, t] = simulate(schedule, 0.01, 0.0, &passes);
    EXPECT_EQ(spp, 300);
    const std::vector<int> expected = {1, 1, 2, 4, 8, 16, 32, 64, 64, 64, 44};
    EXPECT_EQ(passes, expected);
}

TEST(PassSchedule, TimeBudgetEndsWithinHalfASampleOrThreePercent) {
    // From a tiny image (1 spp = 1 ms) to a large one (1 spp = 0.3 s), budgets 1 s to 60 s:
    // the end must be within max(3%, 0.2 s) of the budget, and never more than half a
    // sample's time past it.
    for (const double perSpp : {0.001, 0.013, 0.065, 0.3})
        for (const double budget : {1.0, 9.0, 12.5, 60.0}) {
            PassSchedule schedule(16, budget);
            const auto [spp, t] = simulate(schedule, perSpp, 0.05);
            EXPECT_GE(spp, 1);
            EXPECT_LE(std::abs(t - budget), std::max(0.03 * budget, 0.2))
                << perSpp << " s per spp, budget " << budget << ": ended at " << t;
            EXPECT_LE(t - budget, 0.5 * perSpp + 1e-9);
        }
}

TEST(PassSchedule, ABudgetSpentBeforeTheFirstPassStillRendersOneSample) {
    PassSchedule schedule(16, 0.5);
    const auto [spp, t] = simulate(schedule, 0.1, 2.0);
    EXPECT_EQ(spp, 1);
    EXPECT_NEAR(t, 2.1, 1e-12);
}

}  // namespace
}  // namespace lamina::render
