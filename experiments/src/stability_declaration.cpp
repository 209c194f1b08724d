// `lamina stability` and lamina.stability (stability.h): the options, the inputs read from
// them, the report, and the result as data.
#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/stability.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

StabilityInputs stabilityInputs(const OptionValues& v, const CommandContext& context) {
    StabilityInputs in;
    in.materials = v.texts("materials");
    in.scenes = v.texts("scenes");
    in.spp = int(*v.integer("spp"));
    in.samples = int(*v.integer("samples"));
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

Data stabilityData(const OptionValues& v, const CommandContext& context) {
    const StabilityResult r = runStability(stabilityInputs(v, context));
    Data out = Data::list();
    for (const auto& m : r.models)
        out.append(auditedModelData(m));
    return out;
}

}  // namespace

CommandDecl stabilityDeclaration() {
    const StabilityInputs defaults;
    CommandDecl c;
    c.name = "stability";
    c.help =
        "Extreme-input sweep of BSDF models in float and double (NaN, Inf, negative, energy "
        "gain, weight != eval/pdf, float error) and firefly statistics of stiff scenes";
    c.returns =
        "per model a dict: alphas, cosines, issues and worst_float_error over (alpha, cos theta), "
        "and the totals nan, inf, negative, weight_mismatch, energy_gain, evaluations and "
        "samples; polarised: the Mueller matrices at the singular angles (evaluations, nan, inf, "
        "worst_jump_float, worst_jump_double across +-1 ulp, discontinuities above the bound)";
    c.options = {
        textListOption("materials",
                       "Materials as JSON (default: a conductor, dielectric, standard and "
                       "diffuse set); roughness is replaced by the sweep's alpha")
            .asPositional(),
        outputDirectoryOption(),
        integerOption("samples", "BSDF samples per (alpha, angle) cell", 16, 1 << 24)
            .byDefault(defaults.samples),
        textListOption("scenes", "Stiff scenes to render (e.g. scenes/stress/*.json)")
            .existing()
            .commandLineOnly("the stiff scenes' firefly statistics are a section of the "
                             "report; in Python lamina.render renders them"),
        integerOption("spp", "Samples per pixel of the scene renders", 1, render::kMaxSppOverride)
            .byDefault(defaults.spp)
            .commandLineOnly("of --scenes' renders"),
        resolutionOverrideOption().commandLineOnly("of --scenes' renders"),
        threadsOption().commandLineOnly("of --scenes' renders"),
        maxDepthOption().commandLineOnly("of --scenes' renders"),
        resumeOption(),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        StabilityInputs in = stabilityInputs(v, context);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            StabilityInputs run = in;
            run.keepDirectory = report.directory();
            writeStabilityReport(runStability(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = stabilityData;
    return c;
}

}  // namespace lamina::experiments
