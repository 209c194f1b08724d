// How many samples per pixel each pass of a render takes. Passes double in size (1, 1, 2, 4,
// ... up to 64 spp of the whole image), so early progress is quick and an interruption loses
// little work. With a time budget (--time T) the pass sizes also follow the measured sample
// rate, so the render ends close to T instead of overshooting by most of a 64-spp pass: a
// pass takes at most the samples that fit in the time left, rounded to the nearest whole
// sample per pixel, and the render stops when not even half of one more fits. Every pixel
// gets the same number of samples.
#pragma once

#include <optional>

namespace lamina::render {

class PassSchedule {
  public:
    /// `targetSpp`: the samples per pixel to render (ignored with a time budget);
    /// `seconds`: the time budget, if any.
    PassSchedule(int targetSpp, std::optional<double> seconds);

    /// The size of the next pass after `done` samples per pixel and `elapsed` seconds of
    /// rendering; 0 means the render is complete.
    int next(int done, double elapsed) const;
    /// Records that a pass of `spp` samples per pixel took `seconds`.
    void record(int spp, double seconds);

    bool timed() const { return seconds_.has_value(); }

  private:
    int targetSpp_;
    std::optional<double> seconds_;
    int measuredSpp_ = 0;
    double measuredSeconds_ = 0;
};

}  // namespace lamina::render
