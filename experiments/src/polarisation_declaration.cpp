// `lamina polarisation` and lamina.polarisation (polarisation.h): the options, the inputs read
// from them, the report, and the result as data.
#include <cmath>

#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/polarisation.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

PolarisationInputs polarisationInputs(const OptionValues& v, const CommandContext& context) {
    PolarisationInputs in;
    in.scene = *v.text("scene");
    in.spp = int(v.integer("spp").value_or(0));
    if (const auto seed = v.integer("seed")) in.overrides.seed = std::uint64_t(*seed);
    in.overrides.integrator = v.choice(render::kIntegratorNames, "integrator");
    in.dolpThreshold = *v.number("dolp-threshold");
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

Data flooredData(const FlooredStatistic& s, int spp) {
    const NoiseFloorReading reading = readAgainstFloor(s.value, s.floor, spp);
    Data d = Data::dict();
    d.set("value", s.value);
    d.set("noise_floor", s.floor);
    d.set("resolved", reading.resolved);
    d.set("other_seed", s.otherSeed);
    return d;
}

std::vector<double> asDoubles(const std::vector<float>& values) {
    return {values.begin(), values.end()};
}

Data polarisationData(const OptionValues& v, const CommandContext& context) {
    const PolarisationResult r = runPolarisation(polarisationInputs(v, context));
    const int spp = r.polarised.spp;
    const std::vector<std::size_t> shape{std::size_t(r.height), std::size_t(r.width)};
    Data d = Data::dict();
    d.set("spp", spp);
    d.set("mean_relative_difference", flooredData(r.meanRelative, spp));
    d.set("p95_relative_difference", flooredData(r.p95Relative, spp));
    d.set("mean_delta_e", flooredData(r.meanDeltaE, spp));
    d.set("p95_delta_e", flooredData(r.p95DeltaE, spp));
    d.set("compared_pixels", static_cast<long long>(r.comparedPixels));
    d.set("dolp", Data::array(asDoubles(r.dolp), shape));
    d.set("aolp", Data::array(asDoubles(r.aolp), shape));
    d.set("mean_dolp", r.meanDolp);
    d.set("max_dolp", r.maxDolp);
    d.set("dolp_noise", r.dolpNoise);
    // The relative difference map is NaN where both renders are black: None has no place in
    // an array, so those pixels are 0 here and `compared_pixels` counts the others.
    std::vector<double> relative = asDoubles(r.relative);
    for (double& x : relative)
        if (!std::isfinite(x)) x = 0;
    d.set("relative_difference", Data::array(std::move(relative), shape));
    d.set("delta_e", Data::array(asDoubles(r.ciede2000), shape));
    return d;
}

}  // namespace

CommandDecl polarisationDeclaration() {
    const PolarisationInputs defaults;
    CommandDecl c;
    c.name = "polarisation";
    c.help =
        "What ignoring polarisation costs: a scene in the polarised and the spectral mode, their "
        "relative and CIEDE2000 differences against the noise floor, DoLP and AoLP maps";
    c.returns =
        "a dict: spp; mean_relative_difference, p95_relative_difference, mean_delta_e, "
        "p95_delta_e (each value, noise_floor, resolved, other_seed: between the renders of the "
        "floor's seed); compared_pixels; the polarised "
        "render's dolp and aolp (degrees) as (H, W) arrays (0 where there is no light), "
        "mean_dolp, max_dolp, dolp_noise; the per-pixel relative_difference and delta_e. "
        "Ctrl-C raises KeyboardInterrupt with .partial: {\"renders\": the finished renders (name, "
        "mode, integrator, seed, spp, rgb as an (H, W, 3) array)}";
    c.options = {
        sceneOption(),
        outputDirectoryOption(),
        integerOption("spp", "Samples per pixel of every render (default: the scene's)", 1,
                      render::kMaxSppOverride),
        integerOption("seed", "Seed of the two compared renders (default: the scene's)", 0,
                      render::kMaxSeedOverride),
        nameOption("integrator", "Light transport algorithm (overrides the scene's)",
                   render::kIntegratorNames),
        numberOption("dolp-threshold",
                     "The AoLP map shows pixels whose degree of linear polarisation is at least "
                     "this",
                     0.0, 1.0)
            .byDefault(defaults.dolpThreshold),
        threadsOption(),
        maxDepthOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        resumeOption(),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        PolarisationInputs in = polarisationInputs(v, context);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            PolarisationInputs run = in;
            run.keepDirectory = report.directory();
            writePolarisationReport(runPolarisation(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = polarisationData;
    return c;
}

}  // namespace lamina::experiments
