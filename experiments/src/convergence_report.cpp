// The report of `lamina convergence`: convergence.csv, the figure convergence (png, pdf; drawn
// by the figure module, figure_spec.h), reference_MODE.exr for each rendered reference, and
// summary.md (with its Premises section).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "lamina/experiments/convergence.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

std::string nameOf(render::IntegratorKind kind) {
    return std::string(render::kIntegratorNames.name(kind));
}
std::string nameOf(render::RenderModeKind mode) {
    return std::string(render::kRenderModeNames.name(mode));
}

std::string formatSeconds(double s, double budget) {
    return std::isnan(s) ? formatText("> %.3g s", budget) : formatText("%.3g s", s);
}

std::string formatSlope(double slope) {
    return std::isnan(slope) ? std::string("n/a") : formatText("%.2f", slope);
}

/// Writes the rendered references and says where the reference came from.
std::string writeReferences(const ConvergenceResult& result, const Report& report) {
    const ConvergenceInputs& in = result.inputs;
    if (!in.reference.empty())
        return "reference: " + in.reference + " (given) for every mode, " + result.referenceNote;
    std::string note;
    for (const render::RenderModeKind m : in.modes) {
        const bool rendered = std::any_of(result.references.begin(), result.references.end(),
                                          [m](const RenderedReference& r) { return r.mode == m; });
        if (!rendered)
            note += (note.empty() ? "" : "; ") + renderedReferenceName(m) +
                    ": rendered by the interrupted run this one resumed";
    }
    for (const RenderedReference& ref : result.references) {
        const std::string mode = nameOf(ref.mode), integrator = nameOf(in.referenceIntegrator);
        writeRenderedReference(ref, report);
        note +=
            (note.empty() ? "" : "; ") +
            formatText(
                "reference_%s.exr: %s integrator, %s mode, %d spp (Sobol, its own seed) in "
                "%.1f s",
                mode.c_str(), integrator.c_str(), mode.c_str(), ref.render.spp, ref.render.seconds);
    }
    return note;
}

void writeCsv(const ConvergenceResult& result, const Report& report) {
    std::string csv = ErrorLog::csvHeader("integrator,mode");
    for (const ConvergenceCurve& c : result.curves)
        csv += c.log.csvRows(nameOf(c.integrator) + "," + nameOf(c.mode));
    TablePlot plot;
    plot.title =
        "relMSE against render time: " + std::filesystem::path(result.inputs.scene).stem().string();
    plot.x = "seconds";
    plot.y = {"relmse"};
    plot.groupBy = {"integrator", "mode"};
    plot.xLabel = "render time (s)";
    plot.yLabel = "relMSE (epsilon 1e-2)";
    plot.logX = plot.logY = true;
    report.writeTable("convergence.csv", csv, plot);
}

/// relMSE against render time and against samples per pixel, log-log, each pass with the
/// standard error of its relMSE as a band.
void writePlot(const ConvergenceResult& result, Report& report) {
    const ConvergenceInputs& in = result.inputs;
    LineFigure figure;
    figure.title = "relMSE against render time and samples: " +
                   std::filesystem::path(in.scene).stem().string();
    figure.xLabel = "render time (s)";
    figure.yLabel = "relMSE (epsilon 1e-2)";
    figure.xScale = figure.yScale = AxisScale::Log;
    figure.caption =
        "Standard error of each relMSE: over the image's channel values, the pixels "
        "taken as independent.";
    for (const bool perSample : {false, true}) {
        LinePanel panel{perSample ? "against samples" : "against time",
                        {},
                        perSample ? "samples per pixel" : ""};
        for (const ConvergenceCurve& c : result.curves) {
            LineSeries s;
            s.name = nameOf(c.integrator) + (in.modes.size() > 1 ? " " + nameOf(c.mode) : "");
            if (c.mode == render::RenderModeKind::Spectral) s.style = LineSeries::Style::Dashed;
            s.markers = true;
            for (const auto& r : c.log.rows()) {
                s.x.push_back(perSample ? double(r.spp) : r.seconds);
                s.y.push_back(r.metrics.relmse);
                s.standardError.push_back(r.metrics.relmseStandardError);
            }
            panel.series.push_back(std::move(s));
        }
        figure.panels.push_back(std::move(panel));
    }
    report.addFigure("convergence", figure);
}

/// Each check of each mode's reference and its outcome.
std::string premisesSection(const ConvergenceResult& result) {
    std::string md =
        "\n## Premises\n\nWhat the measurement assumes of its reference, checked before the "
        "first render (its noise once the runs are done): refused stops the experiment, "
        "flagged is allowed but changes how to read the numbers.\n\n"
        "| mode | check | outcome | detail |\n|---|---|---|---|\n";
    for (const ModePremise& p : result.premises)
        md += "| " + nameOf(p.mode) + " | " + p.premise.check + " | " +
              std::string(kPremiseOutcomeNames.name(p.premise.outcome)) + " | " + p.premise.detail +
              " |\n";
    return md;
}

std::string summary(const ConvergenceResult& result, const std::string& referenceNote) {
    const ConvergenceInputs& in = result.inputs;
    std::ostringstream md;
    md << "# Convergence: " << in.scene << "\n\n"
       << referenceNote << ". Each combination rendered for " << in.seconds
       << " s; relMSE = mean((x - ref)^2 / (ref^2 + 1e-2)) over the RGB channels.\n\n"
       << "| integrator | mode | samples/s | spp | relMSE | MSE | slope (time) | slope (spp) |";
    for (const ErrorLevel& l : in.levels)
        md << " time to relMSE " << l.label << " |";
    md << "\n|---|---|---|---|---|---|---|---|";
    for (std::size_t k = 0; k < in.levels.size(); ++k)
        md << "---|";
    md << "\n";
    for (const ConvergenceCurve& c : result.curves) {
        const auto& rows = c.log.rows();
        const ErrorLog::Row last = rows.empty() ? ErrorLog::Row{0, 0, {}} : rows.back();
        md << formatText("| %s | %s | %.3g | %d | %.4g | %.4g | %s | %s |",
                         nameOf(c.integrator).c_str(), nameOf(c.mode).c_str(), c.pathsPerSecond,
                         c.spp, last.metrics.relmse, last.metrics.mse,
                         formatSlope(fittedSlope(rows, SlopeAxis::Seconds)).c_str(),
                         formatSlope(fittedSlope(rows, SlopeAxis::Samples)).c_str());
        for (const ErrorLevel& l : in.levels)
            md << " " << formatSeconds(timeToReach(rows, l.relmse), in.seconds) << " |";
        md << "\n";
    }
    std::string resumed;
    for (const ConvergenceCurve& c : result.curves)
        if (c.resumed)
            resumed += (resumed.empty() ? "" : ", ") + nameOf(c.integrator) + " " + nameOf(c.mode);
    if (!resumed.empty())
        md << "\nResumed: the runs " << resumed
           << " were taken from the interrupted run's runs/ files, not rendered again.\n";
    md << "\nA slope is the least-squares fit of log relMSE against log seconds (time) or log "
          "samples per pixel (spp) after the first tenth of the run: -1 for an unbiased "
          "estimator whose error is all variance; flatter once the reference's own error (or a "
          "bias) dominates. Where the two differ, the seconds of the passes were not in "
          "proportion to their samples (a busy machine, start-up costs); n/a: fewer than three "
          "passes after the first tenth.\n\n"
       << "![relMSE against time and samples](convergence.png)\n";
    md << premisesSection(result);
    return md.str();
}

}  // namespace

std::filesystem::path writeRenderedReference(const RenderedReference& reference,
                                             const Report& report) {
    const std::filesystem::path path = report.file(renderedReferenceName(reference.mode));
    // With its variance: a rerun that takes it as --reference, or resumes, knows its noise.
    render::writeExr(path, *reference.render.film, false, reference.metadata, true);
    return path;
}

void writeConvergenceReport(const ConvergenceResult& result, Report& report) {
    const std::string referenceNote = writeReferences(result, report);
    writeCsv(result, report);
    writePlot(result, report);
    report.addSummary(summary(result, referenceNote));
}

}  // namespace lamina::experiments
