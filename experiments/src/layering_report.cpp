// The report of `lamina layering`: per material STEM_albedo.csv and its figure, STEM_lobes.csv
// and one figure STEM_lobe_THETA per theta_o, per twin the figure STEM_TWIN_error (the relative
// error map over (theta_o, theta_i)), with a scene the renders (PNG previews) and CIEDE2000
// maps; summary.md. The figures are drawn by the figure module (figure_spec.h): NAME.png, .pdf.
#include <cmath>
#include <sstream>

#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/layering.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

/// A twin's name as a file-name part: "fresnel coupling" -> "fresnel".
std::string fileTag(const std::string& twinName) {
    return twinName.substr(0, twinName.find(' '));
}

std::string percent(double fraction) {
    return formatText("%.2f%%", 100.0 * fraction);
}

/// A series of estimates with their standard errors (the band around the line).
LineSeries estimates(const std::string& name, const std::vector<double>& x,
                     const std::vector<MeanEstimate>& values, LineSeries::Style style) {
    LineSeries s{name, x, {}};
    s.style = style;
    for (const MeanEstimate& v : values) {
        s.y.push_back(v.mean);
        s.standardError.push_back(v.standardError);
    }
    return s;
}

void writeAlbedo(const LayeringMaterialResult& m, const LayeringResult& r, Report& report) {
    std::ostringstream csv;
    csv << "theta_o,walk,walk_se";
    for (const LayeringTwinResult& t : m.twins)
        csv << "," << fileTag(t.name) << "," << fileTag(t.name) << "_se";
    csv << "\n";
    for (std::size_t i = 0; i < r.albedoAngles.size(); ++i) {
        const MeanEstimate& w = m.walkAlbedo.values[i];
        csv << r.albedoAngles[i] << "," << w.mean << "," << w.standardError;
        for (const LayeringTwinResult& t : m.twins)
            csv << "," << t.albedo.values[i].mean << "," << t.albedo.values[i].standardError;
        csv << "\n";
    }
    LineFigure figure;
    figure.title = "Directional albedo of " + m.stem + ": walk and analytic twins";
    figure.xLabel = "theta_o (degrees)";
    figure.yLabel = "directional albedo (luminance)";
    figure.xScale = AxisScale::Linear;
    LinePanel panel;
    panel.series.push_back(
        estimates("random walk", r.albedoAngles, m.walkAlbedo.values, LineSeries::Style::Solid));
    panel.series.back().markers = true;
    for (const LayeringTwinResult& t : m.twins)
        panel.series.push_back(estimates("layered, " + t.name, r.albedoAngles, t.albedo.values,
                                         LineSeries::Style::Dashed));
    figure.panels.push_back(std::move(panel));
    TablePlot table;
    table.title = "Directional albedo of " + m.stem;
    table.x = "theta_o";
    table.xLabel = "theta_o (degrees)";
    table.yLabel = "directional albedo (luminance)";
    report.writeTable(m.stem + "_albedo.csv", csv.str(), table);
    report.addFigure(m.stem + "_albedo", figure);
}

void writeLobes(const LayeringMaterialResult& m, const LayeringResult& r, Report& report) {
    std::ostringstream csv;
    csv << "theta_o,theta_i,walk,walk_se";
    for (const LayeringTwinResult& t : m.twins)
        csv << "," << fileTag(t.name);
    csv << "\n";
    for (std::size_t l = 0; l < kLayeringLobeAngles.size(); ++l) {
        const double thetaO = kLayeringLobeAngles[l];
        for (std::size_t i = 0; i < r.lobeAngles.size(); ++i) {
            const MeanEstimate& w = m.walkLobes[l].values[i];
            csv << thetaO << "," << r.lobeAngles[i] << "," << w.mean << "," << w.standardError;
            for (const LayeringTwinResult& t : m.twins)
                csv << "," << t.lobes[l].values[i].mean;
            csv << "\n";
        }
        LineFigure figure;
        figure.title = formatText("f |cos theta_i| of %s in the plane of incidence, theta_o = %g",
                                  m.stem.c_str(), thetaO);
        figure.xLabel = "theta_i (degrees; positive: mirror side)";
        figure.yLabel = "f |cos theta_i| (luminance, 1/sr)";
        figure.xScale = AxisScale::Linear;
        LinePanel panel;
        panel.series.push_back(estimates("random walk", r.lobeAngles, m.walkLobes[l].values,
                                         LineSeries::Style::Solid));
        panel.series.back().markers = true;
        for (const LayeringTwinResult& t : m.twins)
            panel.series.push_back(estimates("layered, " + t.name, r.lobeAngles, t.lobes[l].values,
                                             LineSeries::Style::Dashed));
        figure.panels.push_back(std::move(panel));
        report.addFigure(formatText("%s_lobe_%g", m.stem.c_str(), thetaO), figure);
    }
    TablePlot table;
    table.title = "Lobes of " + m.stem + " in the plane of incidence";
    table.x = "theta_i";
    table.groupBy = {"theta_o"};
    table.xLabel = "theta_i (degrees; positive: mirror side)";
    table.yLabel = "f |cos theta_i| (luminance, 1/sr)";
    report.writeTable(m.stem + "_lobes.csv", csv.str(), table);
}

void writeErrorMap(const LayeringMaterialResult& m, const LayeringTwinResult& t,
                   const LayeringResult& r, Report& report) {
    const int n = int(r.mapAngles.size());
    MapFigure map;
    map.title = "Error of the " + t.name + " twin of " + m.stem +
                " against the walk (f |cos|, plane of incidence, mirror side)";
    map.quantity = "(twin - walk) / walk";
    map.unit = "fraction";
    map.caption = formatText("Where the walk is below %g the error is divided by %g instead.",
                             kAbsoluteFloor, kAbsoluteFloor);
    map.width = map.height = n;
    for (const TwinComparison& c : t.map.comparisons)
        map.values.push_back(float(c.error));
    map.isSigned = true;
    map.x = MapAxis{"theta_i (degrees)", r.mapAngles.front(), r.mapAngles.back(), {}};
    map.y = MapAxis{"theta_o (degrees)", r.mapAngles.front(), r.mapAngles.back(), {}};
    report.addFigure(m.stem + "_" + fileTag(t.name) + "_error", map);
}

/// "0-45" style: the theta_o from 0 up to which every albedo point is within the band.
std::string albedoRange(const LayeringTwinResult& t, const LayeringResult& r, double band) {
    std::size_t i = 0;
    while (i < t.albedo.comparisons.size() && t.albedo.comparisons[i].within(band))
        ++i;
    if (i == 0) return "none";
    if (i == t.albedo.comparisons.size()) return formatText("all (0-%g)", r.albedoAngles.back());
    return formatText("0-%g", r.albedoAngles[i - 1]);
}

std::string bandRow(const std::string& twin, const std::string& what, const BandCounts& c) {
    std::string row = "| " + twin + " | " + what + " | " + std::to_string(c.points) + " |";
    for (std::size_t b = 0; b < kToleranceBands.size(); ++b)
        row += formatText(" %d / %d / %d |", c.within[b], c.beyond[b], c.unresolved[b]);
    return row + " " + std::to_string(c.absolute) + " |\n";
}

std::string albedoTable(const LayeringMaterialResult& m, const LayeringResult& r) {
    std::ostringstream md;
    md << "| theta_o | walk | ";
    for (const LayeringTwinResult& t : m.twins)
        md << t.name << " | error | verdict | ";
    md << "\n|---|---|";
    for (std::size_t k = 0; k < m.twins.size(); ++k)
        md << "---|---|---|";
    md << "\n";
    for (std::size_t i = 0; i < r.albedoAngles.size(); i += 3) {
        const MeanEstimate& w = m.walkAlbedo.values[i];
        md << formatText("| %g | %.4f +- %.4f | ", r.albedoAngles[i], w.mean, w.standardError);
        for (const LayeringTwinResult& t : m.twins) {
            const MeanEstimate& v = t.albedo.values[i];
            const TwinComparison& c = t.albedo.comparisons[i];
            md << formatText("%.4f +- %.4f | %s%s +- %s | %s | ", v.mean, v.standardError,
                             c.error >= 0 ? "+" : "", percent(c.error).c_str(),
                             percent(c.standardError).c_str(),
                             std::string(kAgreementNames.name(c.agreement)).c_str());
        }
        md << "\n";
    }
    return md.str();
}

/// One generated sentence per twin: its albedo error at normal and at the most grazing theta_o,
/// and the share of its lobe points established within 20%.
std::string inShort(const LayeringMaterialResult& m, const LayeringResult& r) {
    std::string md = "In short:";
    const std::size_t last = r.albedoAngles.size() - 1;
    for (std::size_t k = 0; k < m.twins.size(); ++k) {
        const LayeringTwinResult& t = m.twins[k];
        const TwinComparison& a = t.albedo.comparisons.front();
        const TwinComparison& b = t.albedo.comparisons[last];
        BandCounts lobes;
        for (const LayeringValues& l : t.lobes)
            for (const TwinComparison& c : l.comparisons)
                lobes.add(c);
        md += formatText(
            "%s the %s twin's albedo is %s%s +- %s off the walk's at theta_o = 0 and %s%s +- %s "
            "at %g degrees, and %d of its %d lobe points are within 20%%%s",
            k == 0 ? "" : ";", t.name.c_str(), a.error >= 0 ? "+" : "", percent(a.error).c_str(),
            percent(a.standardError).c_str(), b.error >= 0 ? "+" : "", percent(b.error).c_str(),
            percent(b.standardError).c_str(), r.albedoAngles[last], lobes.within[2], lobes.points,
            k + 1 == m.twins.size() ? ".\n" : "");
    }
    return md;
}

std::string writeRenders(const LayeringMaterialResult& m, Report& report) {
    if (m.walkRenders.empty()) return "";
    const char* modes[] = {"rgb", "spectral"};
    std::ostringstream md;
    md << "| twin | mode | mean CIEDE2000 (noise floor) | 95th percentile (noise floor) "
          "|\n|---|---|---|---|\n";
    std::string images;
    for (std::size_t k = 0; k < m.walkRenders.size(); ++k) {
        const std::string walkPng = m.stem + "_walk_" + modes[k] + ".png";
        render::writePngPreview(report.file(walkPng), *m.walkRenders[k].film, 0.0);
        images += "![" + m.stem + " walk, " + modes[k] + "](" + walkPng + ") ";
    }
    for (const LayeringTwinResult& t : m.twins) {
        for (std::size_t k = 0; k < t.renders.size(); ++k) {
            const std::string stem = m.stem + "_" + fileTag(t.name) + "_" + modes[k];
            render::writePngPreview(report.file(stem + ".png"), *t.renders[k].film, 0.0);
            const LayeringRenderComparison& c = t.renderErrors[k];
            const render::RgbImage& image = t.renders[k].image;
            MapFigure map;
            map.title = "CIEDE2000 of " + m.stem + ", " + t.name + " twin against the walk (" +
                        modes[k] + " mode)";
            map.quantity = "CIEDE2000";
            map.caption = "Both renders' noise included.";
            map.width = image.width;
            map.height = image.height;
            map.values = c.ciede2000;
            map.fromZero = true;  // a distance: never negative, 0 is agreement
            report.addFigure(stem + "_ciede2000", map);
            report.addImagePair(
                stem, imagePair(image, t.name + " twin", m.walkRenders[k].image, "random walk",
                                m.stem + ": the " + t.name + " twin against the walk (" + modes[k] +
                                    " mode)"));
            const LayeringRenderComparison& noise = m.walkNoise[k];
            const int spp = t.renders[k].spp;
            md << "| " << t.name << " | " << modes[k] << " | "
               << describeReading(readAgainstFloor(c.meanDeltaE, noise.meanDeltaE, spp), spp)
               << " | " << describeReading(readAgainstFloor(c.p95DeltaE, noise.p95DeltaE, spp), spp)
               << " |\n";
            images += "![" + stem + "](" + stem + ".png) ![" + stem + " CIEDE2000](" + stem +
                      "_ciede2000.png) ";
        }
    }
    md << formatText(
        "\nThe noise floor is the same statistic between the walk's render and a second "
        "one with another seed (the twins share the walk's seed, so their noise is partly "
        "correlated with it: the floor bounds theirs from above). A difference is resolved "
        "when it exceeds %g times its floor; the samples that would resolve one that does "
        "not are estimated with the noise falling as 1/sqrt(spp) and adding in quadrature "
        "to the true difference.\n",
        kResolvedOverFloor);
    md << "\nRenders (walk, then each twin), and the CIEDE2000 maps " << m.stem
       << "_TWIN_MODE_ciede2000.png:\n\n"
       << images << "\n\n";
    return md.str();
}

std::string materialSection(const LayeringMaterialResult& m, const LayeringResult& r,
                            Report& report) {
    std::ostringstream md;
    md << "## " << m.stem << "\n\n```json\n" << m.json << "\n```\n\n";
    if (m.walkMaxDepth > 0) md << "**Not a truth: " << cappedWalkNote(m.walkMaxDepth) << ".**\n\n";
    if (!m.twinNote.empty()) md << "Note: " << m.twinNote << ".\n\n";
    writeAlbedo(m, r, report);
    writeLobes(m, r, report);
    md << "![albedo](" << m.stem << "_albedo.png)\n\n";
    if (m.twins.empty()) {
        md << "The walk's directional albedo alone (" << m.stem << "_albedo.csv, with standard "
           << "errors) and its lobes (" << m.stem << "_lobes.csv).\n\n";
        return md.str();
    }
    md << "Where each twin is within 1%, 5% and 20% of the walk. Counts are within / beyond / "
          "not resolved for each band (error bar +-"
       << formatText("%g", kErrorBarWidth)
       << " standard errors); the last column counts points where the walk is below "
       << formatText("%g", kAbsoluteFloor)
       << " (albedo, or f |cos| in 1/sr), whose error is measured against that floor instead of "
          "the walk's value.\n\n"
       << "| twin | quantity | points | 1% | 5% | 20% | near zero |\n"
       << "|---|---|---|---|---|---|---|\n";
    for (const LayeringTwinResult& t : m.twins) {
        md << bandRow(t.name, "albedo", t.albedo.counts);
        BandCounts lobes;
        for (const LayeringValues& l : t.lobes)
            for (const TwinComparison& c : l.comparisons)
                lobes.add(c);
        md << bandRow(t.name, "lobes (4 theta_o)", lobes);
        md << bandRow(t.name, "error map", t.map.counts);
    }
    md << "\nAlbedo within the band for theta_o in:\n\n| twin | 1% | 5% | 20% "
          "|\n|---|---|---|---|\n";
    for (const LayeringTwinResult& t : m.twins)
        md << "| " << t.name << " | " << albedoRange(t, r, kToleranceBands[0]) << " | "
           << albedoRange(t, r, kToleranceBands[1]) << " | "
           << albedoRange(t, r, kToleranceBands[2]) << " |\n";
    md << "\n" << albedoTable(m, r) << "\n" << inShort(m, r) << "\n";
    for (const LayeringTwinResult& t : m.twins) {
        writeErrorMap(m, t, r, report);
        md << "![" << t.name << " error](" << m.stem << "_" << fileTag(t.name) << "_error.png) ";
    }
    md << "\n\n";
    for (std::size_t l = 0; l < kLayeringLobeAngles.size(); ++l)
        md << formatText("![lobe at %g](%s_lobe_%g.png) ", kLayeringLobeAngles[l], m.stem.c_str(),
                         kLayeringLobeAngles[l]);
    md << "\n\n" << writeRenders(m, report);
    return md.str();
}

}  // namespace

void writeLayeringReport(const LayeringResult& result, Report& report) {
    const LayeringInputs& in = result.inputs;
    std::string md = formatText(
        "# Layering: analytic stacks against the random walk\n\n"
        "Each coated material (the random walk of Guo, Hasan and Zhao 2018) against its "
        "analytic twins: the `layered` stack with the same interface and base, with the "
        "article's (1 - F) coupling and with the albedo coupling (over a rough conductor base, "
        "the conductor seen through the interface in one pass, docs/bsdf.md \"layered over a "
        "conductor\"). RGB mode, double precision, "
        "luminance. The walk's f |cos| at each point is the mean of %d independent estimates "
        "(each the average of the material's `samples` walks); every directional albedo, the "
        "walk's and the twins', is the mean of %d sample() weights; seed %llu. An error is "
        "classified into a band only when its whole error bar (+-%g standard errors) lies "
        "inside it (or, for \"beyond\", outside it); otherwise it is not resolved at this "
        "sample count.\n\n",
        in.estimates, in.albedoSamples, static_cast<unsigned long long>(in.seed), kErrorBarWidth);
    if (result.renderSpp > 0)
        md += formatText(
            "Renders: %s with each BSDF in place of its material \"%s\", %d spp each in RGB and "
            "spectral mode (the scene's integrator, the same seed); the CIEDE2000 of each pixel "
            "between a twin's render and the walk's includes both renders' noise.\n\n",
            in.scene.c_str(), kLayeringSceneMaterial, result.renderSpp);
    for (const LayeringMaterialResult& m : result.materials)
        if (m.walkMaxDepth > 0)
            md += "**" + m.stem + ": " + cappedWalkNote(m.walkMaxDepth) + ".**\n\n";
    for (const LayeringMaterialResult& m : result.materials)
        md += materialSection(m, result, report);
    report.addSummary(md);
}

}  // namespace lamina::experiments
