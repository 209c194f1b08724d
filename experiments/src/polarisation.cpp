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

double meanOf(const std::vector<float>& values) {
    double sum = 0;
    std::size_t n = 0;
    for (const float v : values)
        if (std::isfinite(v)) {
            sum += v;
            ++n;
        }
    return n == 0 ? 0 : sum / double(n);
}

double pixelLuminance(const render::RgbImage& image, std::size_t i) {
    return luminance(
        Rgb<double>(image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]));
}

/// The pixels with light: S0's luminance above kNoLight times the brightest pixel's. A pixel
/// whose light all cancels (crossed mirrors at Brewster's angle) keeps S0 of about 1e-15 of the
/// light from float rounding, whose polarisation means nothing.
constexpr double kNoLight = 1e-6;

std::vector<bool> litPixels(const render::RgbImage& image) {
    double brightest = 0;
    for (std::size_t i = 0; i < image.pixels.size() / 3; ++i)
        brightest = std::max(brightest, pixelLuminance(image, i));
    std::vector<bool> lit(image.pixels.size() / 3);
    for (std::size_t i = 0; i < lit.size(); ++i)
        lit[i] = brightest > 0 && pixelLuminance(image, i) > kNoLight * brightest;
    return lit;
}

/// |Y_a - Y_b| / ((Y_a + Y_b) / 2) per pixel, NaN where both are black. Black is a luminance
/// of at most kNoLight times the brightest pixel's of the two images (a negative luminance, of
/// a colour outside the gamut, counts as 0): otherwise two renders of light that cancels to
/// float rounding would differ by O(1) relative to 1e-15.
std::vector<float> relativeDifferenceMap(const render::RgbImage& a, const render::RgbImage& b) {
    double brightest = 0;
    for (std::size_t i = 0; i < a.pixels.size() / 3; ++i)
        brightest = std::max({brightest, pixelLuminance(a, i), pixelLuminance(b, i)});
    const auto light = [&](double y) { return y > kNoLight * brightest ? y : 0.0; };
    std::vector<float> map(std::size_t(a.width) * a.height);
    for (std::size_t i = 0; i < map.size(); ++i) {
        const double ya = light(pixelLuminance(a, i)), yb = light(pixelLuminance(b, i));
        map[i] = ya + yb > 0 ? float(std::abs(ya - yb) / ((ya + yb) / 2)) : std::nanf("");
    }
    return map;
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

/// The four renders (two modes, two seeds) and what the experiment reads from them.
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
    r.spectral = renderIn(render::RenderModeKind::Spectral, "spectral", "");
    // Both modes again with another seed: the second pair gives the noise of the modes'
    // difference (noise_floor.h, pairedNoise).
    o.seed = hashValues({o.seed.value_or(scene.settings.seed), 0x706f6c666c6f6f72});
    const render::RenderResult polarised2 =
        renderIn(render::RenderModeKind::Polarised, "polarised_seed2",
                 " with another seed (the noise floor)");
    const render::RenderResult spectral2 = renderIn(
        render::RenderModeKind::Spectral, "spectral_seed2", " with another seed (the noise floor)");

    const render::RgbImage p = filmImage(*r.polarised.film), s = filmImage(*r.spectral.film);
    const render::RgbImage p2 = filmImage(*polarised2.film), s2 = filmImage(*spectral2.film);
    r.width = p.width;
    r.height = p.height;
    r.metrics = compareImages(s, p);
    requireComparedValues(r.metrics, s, "the spectral render", p, "the polarised render");
    // The spectral render against the polarised one (the reference); the floor: the same
    // statistic of two images that differ by that difference's noise alone.
    const NoiseOnlyPair noiseOnly = pairedNoise(s, p, s2, p2);

    r.relative = relativeDifferenceMap(s, p);
    r.comparedPixels = std::size_t(std::count_if(r.relative.begin(), r.relative.end(),
                                                 [](float v) { return std::isfinite(v); }));
    const std::vector<float> relFloor = relativeDifferenceMap(noiseOnly.a, noiseOnly.b);
    const std::vector<float> relOther = relativeDifferenceMap(s2, p2);
    r.meanRelative = {meanOf(r.relative), meanOf(relFloor), meanOf(relOther)};
    r.p95Relative = {percentileOf(r.relative, 95), percentileOf(relFloor, 95),
                     percentileOf(relOther, 95)};

    r.ciede2000 = ciede2000Map(s, p);
    const std::vector<float> deFloor = ciede2000Map(noiseOnly.a, noiseOnly.b);
    const std::vector<float> deOther = ciede2000Map(s2, p2);
    r.meanDeltaE = {meanOf(r.ciede2000), meanOf(deFloor), meanOf(deOther)};
    r.p95DeltaE = {percentileOf(r.ciede2000, 95), percentileOf(deFloor, 95),
                   percentileOf(deOther, 95)};

    r.lit = litPixels(p);
    std::vector<float> twinDolp, twinAolp;
    linearPolarisation(*r.polarised.film, r.lit, r.dolp, r.aolp);
    linearPolarisation(*polarised2.film, r.lit, twinDolp, twinAolp);
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
