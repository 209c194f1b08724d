// `lamina convergence` and lamina.convergence (convergence.h): the options, the inputs read
// from them, the report, and the result as data.
#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/convergence_runs.h"
#include "lamina/experiments/interrupted.h"
#include "lamina/experiments/merged_convergence.h"

namespace lamina::experiments {

namespace {

ConvergenceInputs convergenceInputs(const OptionValues& v, const CommandContext& context) {
    ConvergenceInputs in;
    in.scene = *v.text("scene");
    in.reference = v.text("reference").value_or("");
    in.allowCorrelatedReference = v.flag("allow-correlated-reference");
    in.allowNoisyReference = v.flag("allow-noisy-reference");
    in.build = context.build;
    in.levels.clear();
    for (const std::string& level : v.texts("levels"))
        in.levels.push_back({std::stod(level), level});
    in.integrators = v.choices(render::kIntegratorNames, "integrators");
    in.modes = v.choices(render::kRenderModeNames, "modes");
    in.referenceIntegrator = *v.choice(render::kIntegratorNames, "reference-integrator");
    in.seconds = *v.number("time");
    in.referenceSeconds = v.number("reference-time").value_or(0);
    in.overrides.sampler = v.choice(render::kSamplerNames, "sampler");
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

ReportWork convergenceReport(const OptionValues& v, const CommandContext& context) {
    if (const auto merged = v.text("merged")) {
        MergedSetInputs in{*v.text("scene"), {}, v.text("reference").value_or("")};
        for (const std::string& image : splitList(*merged))
            in.images.emplace_back(image);
        // It reads images and renders nothing: a signal ends it at once.
        return {[in](Report& report) {
                    writeMergedSetReport(measureMergedSets(in), report);
                    report.finish();
                    return 0;
                },
                false};
    }
    ConvergenceInputs in = convergenceInputs(v, context);
    in.resume = v.flag("resume");
    return {[in](Report& report) {
        // Each rendered reference is written as soon as it is done, and each finished run
        // (runs/), so a run interrupted later keeps them and --resume continues from them.
        ConvergenceInputs run = in;
        run.keepDirectory = report.directory();
        std::vector<std::string> kept;
        run.onReference = [&](const RenderedReference& r) {
            kept.push_back(writeRenderedReference(r, report).string());
        };
        run.onInterrupted = [&](const ConvergenceResult& partial) {
            for (const ConvergenceCurve& c : partial.curves)
                if (!c.resumed)
                    kept.push_back((report.directory() / runFile(c.integrator, c.mode)).string());
        };
        try {
            writeConvergenceReport(runConvergence(run), report);
        } catch (Interrupted& stopped) {
            for (const std::string& file : kept)
                stopped.kept += (stopped.kept.empty() ? "" : ", ") + file;
            if (!kept.empty())
                stopped.kept +=
                    " (the same command with --resume continues from them without rendering "
                    "them again)";
            throw;
        }
        report.finish();
        return 0;
    }};
}

Data curveData(const ConvergenceCurve& c, const std::vector<ErrorLevel>& levels) {
    const auto& rows = c.log.rows();
    std::vector<double> seconds, mse, relmse, mae;
    std::vector<int> spp;
    for (const auto& row : rows) {
        seconds.push_back(row.seconds);
        spp.push_back(row.spp);
        mse.push_back(row.metrics.mse);
        relmse.push_back(row.metrics.relmse);
        mae.push_back(row.metrics.mae);
    }
    Data reach = Data::dict();
    for (const auto& level : levels)
        reach.set(level.label, Data::number(timeToReach(rows, level.relmse)));
    Data d = Data::dict();
    d.set("integrator", render::kIntegratorNames.name(c.integrator));
    d.set("mode", render::kRenderModeNames.name(c.mode));
    d.set("seconds", Data::array(std::move(seconds)));
    d.set("spp", Data::array(std::move(spp)));
    d.set("mse", Data::array(std::move(mse)));
    d.set("relmse", Data::array(std::move(relmse)));
    d.set("mae", Data::array(std::move(mae)));
    d.set("slope", Data::number(fittedSlope(rows, SlopeAxis::Seconds)));
    d.set("slope_spp", Data::number(fittedSlope(rows, SlopeAxis::Samples)));
    d.set("paths_per_second", c.pathsPerSecond);
    d.set("time_to_relmse", std::move(reach));
    return d;
}

Data resultData(const ConvergenceResult& r) {
    Data curves = Data::list();
    for (const auto& c : r.curves)
        curves.append(curveData(c, r.inputs.levels));
    Data premises = Data::list();
    for (const ModePremise& p : r.premises) {
        Data d = Data::dict();
        d.set("mode", render::kRenderModeNames.name(p.mode));
        d.set("check", p.premise.check);
        d.set("outcome", kPremiseOutcomeNames.name(p.premise.outcome));
        d.set("detail", p.premise.detail);
        premises.append(std::move(d));
    }
    Data out = Data::dict();
    out.set("curves", std::move(curves));
    out.set("reference_note", r.referenceNote);
    out.set("premises", std::move(premises));
    return out;
}

Data convergenceData(const OptionValues& v, const CommandContext& context) {
    ConvergenceInputs in = convergenceInputs(v, context);
    // Interrupted (Ctrl-C in Python) carries what was done: the finished runs and premises.
    std::optional<Data> partial;
    in.onInterrupted = [&](const ConvergenceResult& r) { partial = resultData(r); };
    try {
        return resultData(runConvergence(in));
    } catch (Interrupted& stopped) {
        stopped.partial = std::move(partial);
        throw;
    }
}

}  // namespace

CommandDecl convergenceDeclaration() {
    const ConvergenceInputs defaults;
    std::vector<std::string> levels;
    for (const ErrorLevel& level : defaults.levels)
        levels.push_back(level.label);
    CommandDecl c;
    c.name = "convergence";
    c.help =
        "Error against render time for each integrator and mode: CSV, log-log plot, fitted "
        "slopes, time to reach error levels, a Markdown summary";
    c.returns =
        "a dict: curves (per mode and integrator: the arrays seconds, spp, mse, relmse and mae "
        "after every pass, the fitted slope against seconds and slope_spp against samples, "
        "paths_per_second, time_to_relmse per level), reference_note, and premises (per mode "
        "and check: outcome holds, flagged, not checked or refused, and detail). Ctrl-C raises "
        "KeyboardInterrupt with .partial: the same dict of what was done";
    c.options = {
        sceneOption(),
        outputDirectoryOption(),
        nameListOption("integrators", "Comma-separated list", render::kIntegratorNames,
                       "integrator")
            .byDefault(namesOf(render::kIntegratorNames, defaults.integrators)),
        nameListOption("modes", "Comma-separated list of " + render::kRenderModeNames.list(),
                       render::kRenderModeNames, "mode")
            .byDefault(namesOf(render::kRenderModeNames, defaults.modes)),
        positiveOption("time", "Render time of each combination, seconds", "seconds")
            .byDefault(defaults.seconds)
            .spelledInPython("seconds", "the Python keyword since the first release"),
        fileOption("reference",
                   "Reference EXR (default: rendered first, per mode, with the path integrator)")
            .existing(),
        positiveOption("reference-time",
                       "Render time of each rendered reference (default: 20 x --time)", "seconds")
            .spelledInPython("reference_seconds", "the Python keyword since the first release"),
        threadsOption(),
        maxDepthOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        numberListOption("levels", "relMSE levels for the time-to-error columns")
            .byDefault(levels)
            .differsInPython("a list of numbers (or of texts such as \"1e-2\", kept as the "
                             "labels of time_to_relmse)"),
        nameOption("reference-integrator",
                   "Integrator of the rendered references (bdpt for caustics)",
                   render::kIntegratorNames)
            .byDefault(std::string(render::kIntegratorNames.name(defaults.referenceIntegrator))),
        nameOption("sampler",
                   "Sample generator of the measured renders (the reference always uses Sobol)",
                   render::kSamplerNames),
        flagOption("allow-correlated-reference",
                   "Accept a --reference rendered with the measured renders' sampler and seed "
                   "(their errors are then understated)"),
        flagOption("allow-noisy-reference",
                   "Accept a --reference whose own noise is above 10% of the runs' final "
                   "relMSE (it flattens the slopes; the summary flags it)"),
        flagOption("resume",
                   "Continue the interrupted run in --output's directory: its reference_MODE.exr "
                   "and finished runs/ are used, not rendered again")
            .commandLineOnly("Python keeps no files: an interrupted call's KeyboardInterrupt "
                             "carries .partial, what was done"),
        textOption("merged",
                   "Comma-separated images of `lamina merge`: measure them against "
                   "--reference instead of rendering (merged.csv)")
            .needing("reference")
            .commandLineOnly("merged.csv in the report; in Python read_image and compare "
                             "measure merged images"),
    };
    c.report = convergenceReport;
    c.data = convergenceData;
    return c;
}

}  // namespace lamina::experiments
