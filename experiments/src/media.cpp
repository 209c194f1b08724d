#include "lamina/experiments/media.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/kept_renders.h"

namespace lamina::experiments {

namespace {

/// The seeds of the noise floor's second pair and of a rendered reference, from the first.
constexpr std::uint64_t kSecondSeed = 0x6d656469615f7332;     // "media_s2"
constexpr std::uint64_t kReferenceSeed = 0x6d656469615f7266;  // "media_rf"

/// "NAME", "NAME_2", ...: the first not yet taken.
std::string uniqueName(const std::string& stem, const std::vector<MediaSceneResult>& done) {
    const auto taken = [&](const std::string& n) {
        return std::any_of(done.begin(), done.end(),
                           [&](const MediaSceneResult& r) { return r.name == n; });
    };
    std::string name = stem.empty() ? "scene" : stem;
    for (int i = 2; taken(name); ++i)
        name = (stem.empty() ? "scene" : stem) + "_" + std::to_string(i);
    return name;
}

/// Refuses a given reference on the first premise it fails.
void refuseFailed(const std::vector<Premise>& premises, const std::string& reference) {
    for (const Premise& p : premises)
        if (p.outcome == PremiseOutcome::Refused)
            throw InputError(reference + ": " + describePremise(p));
}

/// The independence of a given reference from the measured renders (referenceCorrelation).
Premise independence(const render::RgbImage& reference, const render::SceneDesc& scene,
                     const render::RenderOptions& measured) {
    if (const auto correlated = referenceCorrelation(reference, scene, measured))
        return {"independence", PremiseOutcome::Refused, *correlated};
    if (!reference.metadata.contains("lamina:seed"))
        return {"independence", PremiseOutcome::NotChecked,
                "the reference has no lamina:seed metadata (another renderer?): its "
                "independence from the measured renders could not be checked"};
    return {"independence", PremiseOutcome::Holds,
            "rendered by lamina with another seed or sampler than the measured renders"};
}

ScoredRender scored(render::RenderResult r, const render::RgbImage& reference, const char* what) {
    ScoredRender s;
    s.render = std::move(r);
    const render::RgbImage image = filmImage(*s.render.film);
    s.metrics = compareImages(image, reference);
    requireComparedValues(s.metrics, image, what, reference, "the reference");
    if (s.metrics.relmse > 0 && s.render.seconds > 0)
        s.efficiency = 1.0 / (s.metrics.relmse * s.render.seconds);
    return s;
}

MediaSceneResult measureScene(const MediaInputs& in, const std::string& file,
                              const std::string& name, KeptRenders& kept) {
    const render::SceneDesc scene = render::loadScene(file);
    if (!scene.hasMedia())
        throw InputError(file +
                         ": the scene has no participating media (docs/media.md): nothing for "
                         "lamina media to compare");
    render::RenderOptions o = in.overrides;
    if (in.spp > 0) o.spp = in.spp;
    requireSeedDependentSampler(o.sampler.value_or(scene.settings.sampler), file);
    const render::IntegratorKind integrator = o.integrator.value_or(scene.settings.integrator);
    render::checkMedia(scene, render::RenderModeKind::Spectral, integrator);
    render::checkMedia(scene, render::RenderModeKind::Rgb, integrator);

    MediaSceneResult r;
    r.scene = file;
    r.name = name;
    o.mode = render::RenderModeKind::Spectral;

    // A given reference is checked before anything is rendered.
    ReferenceFacts facts;
    if (!in.reference.empty()) {
        r.reference = render::readLinearRgbImage(in.reference);
        facts = readReferenceFacts(in.reference, ReferenceSource::Given, r.reference);
        r.premises = referencePremises(facts, scene, o, render::RenderModeKind::Spectral);
        r.premises.push_back(independence(r.reference, scene, o));
        refuseFailed(r.premises, in.reference);
        r.referenceName = in.reference;
        const auto spp = r.reference.metadata.find("lamina:spp");
        if (spp != r.reference.metadata.end()) r.referenceSpp = std::atoi(spp->second.c_str());
    }

    const auto renderIn = [&](render::RenderModeKind mode, bool heroOnly, std::uint64_t seed,
                              const std::string& suffix, const std::string& what) {
        render::RenderOptions ro = o;
        ro.mode = mode;
        ro.seed = seed;
        ro.ablations.noMediaSpectralMis = heroOnly;
        return kept.render(name + "_" + suffix, scene, ro, in.progress, file + " " + what);
    };
    const std::uint64_t seed = o.seed.value_or(scene.settings.seed);
    const std::uint64_t seed2 = hashValues({seed, kSecondSeed});
    using render::RenderModeKind;
    render::RenderResult spectral =
        renderIn(RenderModeKind::Spectral, false, seed, "spectral", "in spectral mode");
    r.rgb = renderIn(RenderModeKind::Rgb, false, seed, "rgb", "in RGB mode");
    const render::RenderResult spectral2 =
        renderIn(RenderModeKind::Spectral, false, seed2, "spectral_seed2",
                 "in spectral mode with another seed (the noise floor)");
    const render::RenderResult rgb2 = renderIn(RenderModeKind::Rgb, false, seed2, "rgb_seed2",
                                               "in RGB mode with another seed (the noise floor)");
    render::RenderResult heroOnly =
        renderIn(RenderModeKind::Spectral, true, seed, "spectral_hero_only",
                 "in spectral mode without spectral MIS (--ablate media-spectral-mis)");

    if (in.reference.empty()) {
        render::RenderOptions ro = o;
        ro.spp =
            in.referenceSpp > 0 ? in.referenceSpp : kReferenceSppFactor * spectral.settings.spp;
        ro.seed = hashValues({seed, kReferenceSeed});
        render::RenderResult ref = kept.render(name + "_reference", scene, ro, in.progress,
                                               file + " reference in spectral mode");
        r.reference = filmImage(*ref.film);
        r.referenceSpp = ref.spp;
        r.referenceSeconds = ref.seconds;
        r.referenceName = "rendered (" + std::to_string(ref.spp) + " spp, its own seed)";
        facts = renderedReferenceFacts(r.referenceName, *ref.film, r.reference);
        r.premises = referencePremises(facts, scene, o, RenderModeKind::Spectral);
    }

    // RGB against spectral, read against the noise of that same-seed difference.
    const render::RgbImage s1 = filmImage(*spectral.film), c1 = filmImage(*r.rgb.film);
    const render::RgbImage s2 = filmImage(*spectral2.film), c2 = filmImage(*rgb2.film);
    r.width = s1.width;
    r.height = s1.height;
    r.spp = spectral.spp;
    r.rgbMetrics = compareImages(c1, s1);
    requireComparedValues(r.rgbMetrics, c1, "the RGB render", s1, "the spectral render");
    const NoiseOnlyPair noiseOnly = pairedNoise(c1, s1, c2, s2);
    r.relative = flooredMap(relativeDifferenceMap, c1, s1, c2, s2, noiseOnly);
    r.ciede2000 = flooredMap(ciede2000Map, c1, s1, c2, s2, noiseOnly);
    r.comparedPixels = std::size_t(std::count_if(r.relative.values.begin(), r.relative.values.end(),
                                                 [](float v) { return std::isfinite(v); }));
    // Two independent spectral renders: the floor a comparison of independent renders has.
    const std::vector<float> independentRelative = relativeDifferenceMap(s2, s1);
    const std::vector<float> independentDeltaE = ciede2000Map(s2, s1);
    r.independent = {meanOfFinite(independentRelative), percentileOf(independentRelative, 95),
                     meanOfFinite(independentDeltaE), percentileOf(independentDeltaE, 95)};

    r.spectralMis = scored(std::move(spectral), r.reference, "the spectral render");
    r.heroOnly = scored(std::move(heroOnly), r.reference, "the render without spectral MIS");
    const double smallest = std::min(r.spectralMis.metrics.relmse, r.heroOnly.metrics.relmse);
    // The noise adds to both relMSEs alike: it shrinks their ratio, the gain of spectral MIS.
    const Premise noise = noisePremise(
        facts, smallest, in.allowNoisyReference,
        {false,
         "it makes the two relMSEs' ratio (spectral MIS's gain) noticeably smaller than it is",
         "a larger --reference-spp makes a quieter reference"});
    r.premises.push_back(noise);
    if (noise.outcome == PremiseOutcome::Refused)
        throw InputError(in.reference + ": " + describePremise(noise));
    return r;
}

}  // namespace

MediaResult runMedia(const MediaInputs& in) {
    if (in.scenes.empty()) throw InputError("lamina media: give at least one scene");
    if (!in.reference.empty() && in.scenes.size() > 1)
        throw InputError("--reference " + in.reference +
                         ": a reference is one scene's; give one scene with it");
    KeptRenders kept(in.keepDirectory, in.resume);
    return keepingOnInterrupt(kept, [&] {
        MediaResult result;
        for (const std::string& file : in.scenes) {
            const std::string name =
                uniqueName(std::filesystem::path(file).stem().string(), result.scenes);
            result.scenes.push_back(measureScene(in, file, name, kept));
        }
        return result;
    });
}

}  // namespace lamina::experiments
