#include "lamina/experiments/polarisation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/core/spectrum.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/noise_floor.h"

namespace lamina::experiments {

namespace {

/// The pixels with light: S0's luminance above kNoLight times the brightest pixel's (whose
/// polarisation means something).

std::vector<bool> litPixels(const render::RgbImage& image) {
    double brightest = 0;
    for (std::size_t i = 0; i < image.pixels.size() / 3; ++i)
        brightest = std::max(brightest, pixelLuminance(image, i));
    std::vector<bool> lit(image.pixels.size() / 3);
    for (std::size_t i = 0; i < lit.size(); ++i)
        lit[i] = brightest > 0 && pixelLuminance(image, i) > kNoLight * brightest;
    return lit;
}

/// DoLP and AoLP (degrees) of each lit pixel from the luminance of its Stokes layers; 0 in the
/// others.
void linearPolarisation(const render::Film& film, const std::vector<bool>& lit,
                        std::vector<float>& dolp, std::vector<float>& aolp) {
    dolp.assign(std::size_t(film.width()) * film.height(), 0.0f);
    aolp.assign(dolp.size(), 0.0f);
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const std::size_t i = std::size_t(y) * film.width() + x;
            if (!lit[i]) continue;
            const auto s = film.stokes(x, y);
            const double s0 = luminance(s[0]), s1 = luminance(s[1]), s2 = luminance(s[2]);
            // A noisy pixel can have |S1, S2| > S0; a degree of polarisation is at most 1.
            dolp[i] = float(std::min(1.0, std::hypot(s1, s2) / s0));
            aolp[i] = float(0.5 * std::atan2(s2, s1) * 180.0 / std::numbers::pi);
        }
}

/// The unpolarised render `mode` (and its twin of the floor's seed) against the polarised
/// render `p` (and its twin).
AgainstPolarised againstPolarised(render::RenderResult mode, const render::RenderResult& modeTwin,
                                  const render::RgbImage& p, const render::RgbImage& pTwin,
                                  const char* what) {
    AgainstPolarised a;
    a.render = std::move(mode);
    const render::RgbImage s = filmImage(*a.render.film), sTwin = filmImage(*modeTwin.film);
    a.metrics = compareImages(s, p);
    requireComparedValues(a.metrics, s, what, p, "the polarised render");

    // A per-pixel statistic of the pair, its mean and 95th percentile against their floors
    // (noise_floor.h).
    const NoiseOnlyPair noiseOnly = pairedNoise(s, p, sTwin, pTwin);
    FlooredMap relative = flooredMap(relativeDifferenceMap, s, p, sTwin, pTwin, noiseOnly);
    FlooredMap de = flooredMap(ciede2000Map, s, p, sTwin, pTwin, noiseOnly);
    a.relative = std::move(relative.values);
    a.meanRelative = relative.mean;
    a.p95Relative = relative.p95;
    a.ciede2000 = std::move(de.values);
    a.meanDeltaE = de.mean;
    a.p95DeltaE = de.p95;
    a.comparedPixels = std::size_t(std::count_if(a.relative.begin(), a.relative.end(),
                                                 [](float v) { return std::isfinite(v); }));
    return a;
}

/// The six renders (three modes, two seeds) and what the experiment reads from them.
PolarisationResult comparePolarisation(const PolarisationInputs& in, const render::SceneDesc& scene,
                                       render::RenderOptions o, KeptRenders& kept) {
    PolarisationResult r;
    r.scene = in.scene;
    r.dolpThreshold = in.dolpThreshold;
    const auto renderIn = [&](render::RenderModeKind mode, const std::string& name,
                              const std::string& what) {
        o.mode = mode;
        return kept.render(
            name, scene, o, in.progress,
            in.scene + " in " + std::string(render::kRenderModeNames.name(mode)) + " mode" + what);
    };
    r.polarised = renderIn(render::RenderModeKind::Polarised, "polarised", "");
    render::RenderResult spectral = renderIn(render::RenderModeKind::Spectral, "spectral", "");
    render::RenderResult rgb = renderIn(render::RenderModeKind::Rgb, "rgb", "");
    // Each mode again with another seed: the second pairs give the noise of the modes'
    // differences (noise_floor.h, pairedNoise).
    o.seed = hashValues({o.seed.value_or(scene.settings.seed), 0x706f6c666c6f6f72});
    const std::string again = " with another seed (the noise floor)";
    const render::RenderResult polarisedTwin =
        renderIn(render::RenderModeKind::Polarised, "polarised_seed2", again);
    const render::RenderResult spectralTwin =
        renderIn(render::RenderModeKind::Spectral, "spectral_seed2", again);
    const render::RenderResult rgbTwin = renderIn(render::RenderModeKind::Rgb, "rgb_seed2", again);

    const render::RgbImage p = filmImage(*r.polarised.film);
    const render::RgbImage pTwin = filmImage(*polarisedTwin.film);
    r.width = p.width;
    r.height = p.height;
    r.spectral =
        againstPolarised(std::move(spectral), spectralTwin, p, pTwin, "the spectral render");
    r.rgb = againstPolarised(std::move(rgb), rgbTwin, p, pTwin, "the RGB render");

    r.lit = litPixels(p);
    std::vector<float> twinDolp, twinAolp;
    linearPolarisation(*r.polarised.film, r.lit, r.dolp, r.aolp);
    linearPolarisation(*polarisedTwin.film, r.lit, twinDolp, twinAolp);
    double sum = 0, noise = 0;
    std::size_t lit = 0;
    for (std::size_t i = 0; i < r.dolp.size(); ++i) {
        if (!r.lit[i]) continue;
        sum += r.dolp[i];
        noise += std::abs(double(r.dolp[i]) - twinDolp[i]);
        r.maxDolp = std::max(r.maxDolp, double(r.dolp[i]));
        ++lit;
    }
    if (lit > 0) {
        r.meanDolp = sum / double(lit);
        r.dolpNoise = noise / double(lit);
    }
    return r;
}

}  // namespace

PolarisationResult runPolarisation(const PolarisationInputs& in) {
    const render::SceneDesc scene = render::loadScene(in.scene);
    render::RenderOptions o = in.overrides;
    requireSeedDependentSampler(o.sampler.value_or(scene.settings.sampler), in.scene);
    if (in.spp > 0) o.spp = in.spp;
    KeptRenders kept(in.keepDirectory, in.resume);
    return keepingOnInterrupt(kept, [&] { return comparePolarisation(in, scene, o, kept); });
}

}  // namespace lamina::experiments
