// `lamina stability` and lamina.stability (stability.h): the options, the inputs read from
// them, the report, and the result as data.
#include "declarations.h"
#include "lamina/experiments/command_options.h"
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
    in.progress = context.progress;
    return in;
}

Data modelData(const AuditedModel& m) {
    const StabilityReport& a = m.audit;
    std::vector<int> issues;
    std::vector<double> floatError;
    for (std::size_t i = 0; i < a.alphas.size(); ++i)
        for (std::size_t j = 0; j < a.cosines.size(); ++j) {
            issues.push_back(a.at(i, j).issues());
            floatError.push_back(a.at(i, j).worstFloatError);
        }
    const std::vector<std::size_t> shape = {a.alphas.size(), a.cosines.size()};
    const StabilityCell t = a.total();
    Data d = Data::dict();
    d.set("material", m.json);
    d.set("alphas", Data::numbers(a.alphas));
    d.set("cosines", Data::numbers(a.cosines));
    d.set("issues", Data::array(std::move(issues), shape));
    d.set("worst_float_error", Data::array(std::move(floatError), shape));
    d.set("nan", t.nan);
    d.set("inf", t.inf);
    d.set("negative", t.negative);
    d.set("weight_mismatch", t.weightMismatch);
    d.set("energy_gain", t.energyGain);
    d.set("evaluations", t.evaluations);
    d.set("samples", t.samples);
    const PolarisedStabilityReport& p = m.polarised;
    Data polarised = Data::dict();
    polarised.set("evaluations", p.evaluations);
    polarised.set("nan", p.nan);
    polarised.set("inf", p.inf);
    polarised.set("worst_jump_float", p.worstJumpFloat);
    polarised.set("worst_jump_double", p.worstJumpDouble);
    polarised.set("discontinuities", p.discontinuities);
    d.set("polarised", std::move(polarised));
    return d;
}

Data stabilityData(const OptionValues& v, const CommandContext& context) {
    const StabilityResult r = runStability(stabilityInputs(v, context));
    Data out = Data::list();
    for (const auto& m : r.models)
        out.append(modelData(m));
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
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        const StabilityInputs in = stabilityInputs(v, context);
        return {[in](Report& report) {
            writeStabilityReport(runStability(in), report);
            report.finish();
            return 0;
        }};
    };
    c.data = stabilityData;
    return c;
}

}  // namespace lamina::experiments
