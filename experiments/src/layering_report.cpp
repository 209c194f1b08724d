// The report of `lamina layering`: per material STEM_albedo.csv/.svg, STEM_lobes.csv and one
// STEM_lobe_THETA.svg per theta_o, per twin STEM_TWIN_error.svg (the relative error map over
// (theta_o, theta_i)), with a scene the renders (PNG previews) and CIEDE2000 maps; summary.md.
#include <cmath>
#include <sstream>

#include "lamina/experiments/layering.h"
#include "lamina/experiments/svg_heat_map.h"
#include "lamina/experiments/svg_plot.h"
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

void writeAlbedo(const LayeringMaterialResult& m, const LayeringResult& r, const Report& report) {
    std::ostringstream csv;
    csv << "theta_o,walk,walk_se";
    for (const LayeringTwinResult& t : m.twins)
        csv << "," << fileTag(t.name) << "," << fileTag(t.name) << "_se";
    csv << "\n";
    SvgPlot plot("Directional albedo of " + m.stem + ": walk and analytic twins",
                 "theta_o (degrees)", "directional albedo (luminance)");
    SvgPlot::Series walk{"random walk", {}, {}, false, true};
    for (std::size_t i = 0; i < r.albedoAngles.size(); ++i) {
        const MeanEstimate& w = m.walkAlbedo.values[i];
        csv << r.albedoAngles[i] << "," << w.mean << "," << w.standardError;
        for (const LayeringTwinResult& t : m.twins)
            csv << "," << t.albedo.values[i].mean << "," << t.albedo.values[i].standardError;
        csv << "\n";
        walk.x.push_back(r.albedoAngles[i]);
        walk.y.push_back(w.mean);
    }
    plot.add(std::move(walk));
    for (const LayeringTwinResult& t : m.twins) {
        SvgPlot::Series s{"layered, " + t.name, {}, {}, true};
        for (std::size_t i = 0; i < r.albedoAngles.size(); ++i) {
            s.x.push_back(r.albedoAngles[i]);
            s.y.push_back(t.albedo.values[i].mean);
        }
        plot.add(std::move(s));
    }
    TablePlot table;
    table.title = "Directional albedo of " + m.stem;
    table.x = "theta_o";
    table.xLabel = "theta_o (degrees)";
    table.yLabel = "directional albedo (luminance)";
    report.writeTable(m.stem + "_albedo.csv", csv.str(), table);
    report.writeFigure(m.stem + "_albedo.svg", plot);
}

void writeLobes(const LayeringMaterialResult& m, const LayeringResult& r, const Report& report) {
    std::ostringstream csv;
    csv << "theta_o,theta_i,walk,walk_se";
    for (const LayeringTwinResult& t : m.twins)
        csv << "," << fileTag(t.name);
    csv << "\n";
    for (std::size_t l = 0; l < kLayeringLobeAngles.size(); ++l) {
        const double thetaO = kLayeringLobeAngles[l];
        SvgPlot plot(formatText("f |cos theta_i| of %s in the plane of incidence, theta_o = %g",
                                m.stem.c_str(), thetaO),
                     "theta_i (degrees; positive: mirror side)",
                     "f |cos theta_i| (luminance, 1/sr)");
        SvgPlot::Series walk{"random walk", {}, {}, false, true};
        for (std::size_t i = 0; i < r.lobeAngles.size(); ++i) {
            const MeanEstimate& w = m.walkLobes[l].values[i];
            csv << thetaO << "," << r.lobeAngles[i] << "," << w.mean << "," << w.standardError;
            for (const LayeringTwinResult& t : m.twins)
                csv << "," << t.lobes[l].values[i].mean;
            csv << "\n";
            walk.x.push_back(r.lobeAngles[i]);
            walk.y.push_back(w.mean);
        }
        plot.add(std::move(walk));
        for (const LayeringTwinResult& t : m.twins) {
            SvgPlot::Series s{"layered, " + t.name, {}, {}, true};
            for (std::size_t i = 0; i < r.lobeAngles.size(); ++i) {
                s.x.push_back(r.lobeAngles[i]);
                s.y.push_back(t.lobes[l].values[i].mean);
            }
            plot.add(std::move(s));
        }
        report.writeFigure(formatText("%s_lobe_%g.svg", m.stem.c_str(), thetaO), plot);
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
                   const LayeringResult& r, const Report& report) {
    const int n = int(r.mapAngles.size());
    std::vector<float> values;
    for (const TwinComparison& c : t.map.comparisons)
        values.push_back(float(c.error));
    SvgHeatMap map("Error of the " + t.name + " twin of " + m.stem +
                       " against the walk (f |cos|, plane of incidence, mirror side)",
                   n, n, values);
    map.setAxes({"theta_i (degrees)", r.mapAngles.front(), r.mapAngles.back(), {}},
                {"theta_o (degrees)", r.mapAngles.front(), r.mapAngles.back(), {}});
    map.setScale(Palette::Diverging, -0.2, 0.2,
                 "(twin - walk) / walk (or / 1e-4 where the walk is below 1e-4), saturated at 20%");
    map.write(report.file(m.stem + "_" + fileTag(t.name) + "_error.svg"));
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

std::string writeRenders(const LayeringMaterialResult& m, const Report& report) {
    if (m.walkRenders.empty()) return "";
    const char* modes[] = {"rgb", "spectral"};
    std::ostringstream md;
    md << "| twin | mode | mean CIEDE2000 | 95th percentile |\n|---|---|---|---|\n";
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
            SvgHeatMap map("CIEDE2000 of " + m.stem + ", " + t.name + " twin against the walk (" +
                               modes[k] + " mode)",
                           image.width, image.height, c.ciede2000);
            map.setScale(Palette::Sequential, 0, 10, "CIEDE2000 (saturated at 10)");
            map.write(report.file(stem + "_ciede2000.svg"), report.file(stem + "_ciede2000.png"));
            md << formatText("| %s | %s | %.2f | %.2f |\n", t.name.c_str(), modes[k], c.meanDeltaE,
                             c.p95DeltaE);
            images += "![" + stem + "](" + stem + ".png) ";
        }
    }
    md << "\nRenders (walk, then each twin), and the CIEDE2000 maps " << m.stem
       << "_TWIN_MODE_ciede2000.svg:\n\n"
       << images << "\n\n";
    return md.str();
}

std::string materialSection(const LayeringMaterialResult& m, const LayeringResult& r,
                            const Report& report) {
    std::ostringstream md;
    md << "## " << m.stem << "\n\n```json\n" << m.json << "\n```\n\n";
    if (m.walkMaxDepth > 0) md << "**Not a truth: " << cappedWalkNote(m.walkMaxDepth) << ".**\n\n";
    if (!m.twinNote.empty()) md << "Note: " << m.twinNote << ".\n\n";
    writeAlbedo(m, r, report);
    writeLobes(m, r, report);
    md << "![albedo](" << m.stem << "_albedo.svg)\n\n";
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
        md << "![" << t.name << " error](" << m.stem << "_" << fileTag(t.name) << "_error.svg) ";
    }
    md << "\n\n";
    for (std::size_t l = 0; l < kLayeringLobeAngles.size(); ++l)
        md << formatText("![lobe at %g](%s_lobe_%g.svg) ", kLayeringLobeAngles[l], m.stem.c_str(),
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
