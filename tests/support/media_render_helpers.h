// What the tests of renders through media share (tests/render/media_render_test.cpp,
// grid_media_test.cpp): a render's per-channel image means with their standard errors, and
// Welch's statistic of two of them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "render_helpers.h"

namespace lamina::testing {

/// The image mean of each channel, with its standard error.
struct Rendered {
    ImageMean channel[3];
};

/// `scene` rendered with the given mode, samples per pixel, seed, next-event estimation and
/// integrator; no sample may be rejected.
inline Rendered renderMeans(const render::SceneDesc& scene, render::RenderModeKind mode, int spp,
                            std::uint64_t seed, bool nextEvent = true,
                            render::IntegratorKind integrator = render::IntegratorKind::Path) {
    render::SceneDesc s = scene;
    s.settings.nextEvent = nextEvent;
    render::RenderOptions o;
    o.integrator = integrator;
    o.mode = mode;
    o.spp = spp;
    o.seed = seed;
    const render::RenderResult r = render::renderScene(s, o);
    EXPECT_EQ(r.film->rejectedSamples(), 0u);
    Rendered out;
    for (int c = 0; c < 3; ++c)
        out.channel[c] = channelMean(*r.film, c);
    return out;
}

/// Welch's statistic of two independent image means (normal approximation: the degrees of
/// freedom are in the thousands).
inline double welch(const ImageMean& a, const ImageMean& b) {
    return (a.mean - b.mean) /
           std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
}

}  // namespace lamina::testing
