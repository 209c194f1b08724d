// `lamina media` and lamina.media (media.h): the options, the inputs read from them, the report,
// and the result as data.
#include <cmath>

#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/media.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

MediaInputs mediaInputs(const OptionValues& v, const CommandContext& context) {
    MediaInputs in;
    in.scenes = v.texts("scenes");
    in.spp = int(v.integer("spp").value_or(0));
    in.referenceSpp = int(v.integer("reference-spp").value_or(0));
    in.reference = v.text("reference").value_or("");
    in.allowNoisyReference = v.flag("allow-noisy-reference");
    if (const auto seed = v.integer("seed")) in.overrides.seed = std::uint64_t(*seed);
    in.overrides.integrator = v.choice(render::kIntegratorNames, "integrator");
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

Data flooredData(const FlooredStatistic& s, int spp) {
    Data d = Data::dict();
    d.set("value", s.value);
    d.set("noise_floor", s.floor);
    d.set("resolved", readAgainstFloor(s.value, s.floor, spp).resolved);
    d.set("other_seed", s.otherSeed);
    return d;
}

Data scoredData(const ScoredRender& s) {
    Data d = Data::dict();
    d.set("relmse", s.metrics.relmse);
    d.set("relmse_standard_error", s.metrics.relmseStandardError);
    d.set("seconds", s.render.seconds);
    d.set("efficiency", s.efficiency);
    return d;
}

Data sceneData(const MediaSceneResult& r) {
    const std::vector<std::size_t> shape{std::size_t(r.height), std::size_t(r.width)};
    Data d = Data::dict();
    d.set("scene", r.scene);
    d.set("spp", r.spp);
    d.set("mean_relative_difference", flooredData(r.relative.mean, r.spp));
    d.set("p95_relative_difference", flooredData(r.relative.p95, r.spp));
    d.set("mean_delta_e", flooredData(r.ciede2000.mean, r.spp));
    d.set("p95_delta_e", flooredData(r.ciede2000.p95, r.spp));
    Data independent = Data::dict();
    independent.set("mean_relative_difference", r.independent.meanRelative);
    independent.set("p95_relative_difference", r.independent.p95Relative);
    independent.set("mean_delta_e", r.independent.meanDeltaE);
    independent.set("p95_delta_e", r.independent.p95DeltaE);
    d.set("independent_spectral", std::move(independent));
    d.set("compared_pixels", static_cast<long long>(r.comparedPixels));
    // NaN where both renders are black: 0 in the array, `compared_pixels` counts the others.
    std::vector<double> relative(r.relative.values.begin(), r.relative.values.end());
    for (double& x : relative)
        if (!std::isfinite(x)) x = 0;
    d.set("relative_difference", Data::array(std::move(relative), shape));
    d.set("delta_e",
          Data::array(std::vector<double>(r.ciede2000.values.begin(), r.ciede2000.values.end()),
                      shape));
    d.set("spectral_mis", scoredData(r.spectralMis));
    d.set("hero_only", scoredData(r.heroOnly));
    d.set("reference", r.referenceName);
    d.set("reference_spp", r.referenceSpp);
    Data premises = Data::list();
    for (const Premise& p : r.premises) {
        Data pd = Data::dict();
        pd.set("check", p.check);
        pd.set("outcome", kPremiseOutcomeNames.name(p.outcome));
        pd.set("detail", p.detail);
        premises.append(std::move(pd));
    }
    d.set("premises", std::move(premises));
    return d;
}

Data mediaData(const OptionValues& v, const CommandContext& context) {
    const MediaResult r = runMedia(mediaInputs(v, context));
    Data out = Data::list();
    for (const MediaSceneResult& s : r.scenes)
        out.append(sceneData(s));
    return out;
}

}  // namespace

CommandDecl mediaDeclaration() {
    CommandDecl c;
    c.name = "media";
    c.help =
        "Chromatic participating media: RGB against spectral mode (relative and CIEDE2000 "
        "differences against the noise floor) and the efficiency of spectral MIS over the "
        "wavelengths against the hero wavelength alone, against a converged reference";
    c.returns =
        "a list, per scene a dict: scene, spp; mean_relative_difference, "
        "p95_relative_difference, mean_delta_e, p95_delta_e (RGB against spectral mode; each "
        "value, noise_floor, resolved, other_seed: between the renders of the floor's seed); "
        "independent_spectral (the same four statistics between two independent spectral "
        "renders); compared_pixels; the per-pixel relative_difference and delta_e as (H, W) "
        "arrays; spectral_mis and hero_only (relmse, relmse_standard_error, seconds, efficiency = "
        "1 / (relmse x seconds)); reference, reference_spp; premises (check, outcome, detail). "
        "Ctrl-C raises KeyboardInterrupt with .partial: {\"renders\": the finished renders "
        "(name, mode, integrator, seed, spp, rgb as an (H, W, 3) array)}";
    c.options = {
        textListOption("scenes", "Scene files with participating media")
            .asPositional()
            .asRequired(),
        outputDirectoryOption(),
        integerOption("spp", "Samples per pixel of the compared renders (default: the scene's)", 1,
                      render::kMaxSppOverride),
        integerOption("reference-spp",
                      "Samples per pixel of the rendered reference (default: 16 x spp)", 1,
                      render::kMaxSppOverride)
            .excluding("reference"),
        fileOption("reference",
                   "A converged spectral render of the (one) scene to score against, instead of "
                   "rendering one; its premises are checked (mode, resolution, scene files, max "
                   "depth, independence, noise)")
            .existing(),
        flagOption("allow-noisy-reference",
                   "Score against a given --reference whose own noise exceeds 10% of the "
                   "smaller relMSE anyway (the summary flags it)")
            .needing("reference"),
        integerOption("seed", "Seed of the compared renders (default: the scene's)", 0,
                      render::kMaxSeedOverride),
        nameOption("integrator", "Light transport algorithm (overrides the scene's)",
                   render::kIntegratorNames),
        threadsOption(),
        maxDepthOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        resumeOption(),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        MediaInputs in = mediaInputs(v, context);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            MediaInputs run = in;
            run.keepDirectory = report.directory();
            writeMediaReport(runMedia(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = mediaData;
    return c;
}

}  // namespace lamina::experiments
