// The report of `lamina stability`: heat maps per model over (alpha, angle) and summary.md.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "lamina/core/json_reader.h"
#include "lamina/experiments/stability.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

std::string cellText(const StabilityCell& t) {
    return formatText("%d | %d | %d | %d | %d | %.2g", t.nan, t.inf, t.negative, t.energyGain,
                      t.weightMismatch, t.worstFloatError);
}

/// The file stem of a model: its number and its material type ("model2_conductor").
std::string modelStem(std::size_t index, const std::string& json) {
    std::string type = "material";
    const Json j = Json::parse(json, nullptr, false);
    if (j.is_object() && j.contains("type") && j["type"].is_string()) type = j["type"];
    for (char& c : type)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
    return "model" + std::to_string(index + 1) + "_" + type;
}

/// Two figures per model over (alpha, cos theta_o), each cell one audited pair of parameters:
/// the number of issues and the worst float-against-double error, both on log scales.
void addHeatMaps(Report& report, const std::string& stem, const std::string& json,
                 const StabilityReport& r) {
    const int w = int(r.cosines.size()), h = int(r.alphas.size());
    std::vector<float> issues(std::size_t(w) * h), error(std::size_t(w) * h);
    double most = 1;
    for (std::size_t a = 0; a < r.alphas.size(); ++a)
        for (std::size_t c = 0; c < r.cosines.size(); ++c) {
            const StabilityCell& cell = r.at(a, c);
            issues[a * std::size_t(w) + c] = float(std::log10(1.0 + double(cell.issues())));
            error[a * std::size_t(w) + c] = float(std::log10(std::max(cell.worstFloatError, 1e-8)));
            most = std::max(most, double(issues[a * std::size_t(w) + c]));
        }
    MapAxis x{"cos(theta_o)", 0, 0, {}}, y{"alpha (GGX roughness)", 0, 0, {}};
    for (double c : r.cosines)
        x.categories.push_back(formatText("%g", c));
    for (double a : r.alphas)
        y.categories.push_back(formatText("%g", a));
    // One map over the sweep's grid: what is common to both figures.
    const auto gridMap = [&](std::string title, std::string quantity, std::string unit,
                             std::vector<float> values) {
        MapFigure map;
        map.title = std::move(title) + ": " + json;
        map.quantity = std::move(quantity);
        map.unit = std::move(unit);
        map.width = w;
        map.height = h;
        map.values = std::move(values);
        map.x = x;
        map.y = y;
        return map;
    };
    MapFigure issueMap =
        gridMap("Issues (NaN, Inf, negative, energy gain, weight != eval/pdf)",
                "log10(1 + issues per cell)", "count, log scale", std::move(issues));
    issueMap.fromZero = true;  // 0: no issue
    issueMap.upper = most;     // the worst cell: nothing lies beyond
    report.addFigure(stem + "_issues", issueMap);
    MapFigure errorMap = gridMap("Worst relative error of float against double",
                                 "log10(relative error)", "floored at -8", std::move(error));
    // The whole range, from the smallest value (at most the floor, -8) to 0 (an error of 100%).
    errorMap.percentile = 100;
    errorMap.upper = 0;
    report.addFigure(stem + "_float_error", errorMap);
}

std::string modelsSection(const StabilityResult& result, Report& report) {
    std::ostringstream md;
    md << "## BSDF models on extreme inputs\n\nalpha in {";
    for (double a : kStabilityAlphas)
        md << a << (a == kStabilityAlphas.back() ? "" : ", ");
    md << "} (models without a roughness: one row), cos(theta_o) in {";
    for (double c : kStabilityCosines)
        md << c << (c == kStabilityCosines.back() ? "" : ", ");
    md << "}; per cell " << result.inputs.samples
       << " samples and 71 evaluation directions in both transport modes, float and double.\n\n"
          "| model | NaN | Inf | negative | energy gain | weight != eval/pdf | worst float/double "
          "error |\n|---|---|---|---|---|---|---|\n";
    std::string maps;
    for (std::size_t i = 0; i < result.models.size(); ++i) {
        const AuditedModel& m = result.models[i];
        const std::string stem = modelStem(i, m.json);
        addHeatMaps(report, stem, m.json, m.audit);
        md << "| `" << m.json << "` | " << cellText(m.audit.total()) << " |\n";
        maps += "![" + stem + " issues](" + stem + "_issues.png) ![" + stem + " float error](" +
                stem + "_float_error.png)\n\n";
    }
    md << "\nHeat maps per model, named by its number and material type "
          "(`modelN_TYPE_issues.png`: issues per (alpha, cos theta_o) cell; "
          "`modelN_TYPE_float_error.png`: the worst float error against double; each also as "
          "PDF), each with its parameter values on the axes and a colour bar.\n\n"
       << maps;
    return md.str();
}

std::string scenesSection(const StabilityResult& result) {
    std::ostringstream md;
    md << "## Stiff scenes\n\n"
       << result.inputs.spp
       << " spp each, path integrator, RGB mode. A rejected sample had a NaN, Inf or negative "
          "value and was not added; the firefly ratio is the largest sample's luminance over "
          "the image's mean luminance.\n\n"
          "| scene | rejected samples | largest sample | image mean | firefly ratio |\n"
          "|---|---|---|---|---|\n";
    for (const StiffSceneRender& s : result.scenes)
        md << formatText("| %s | %llu | %.4g | %.4g | %.3g |\n",
                         std::filesystem::path(s.scene).filename().string().c_str(),
                         static_cast<unsigned long long>(s.rejectedSamples), s.largestSample,
                         s.meanLuminance,
                         s.meanLuminance > 0 ? s.largestSample / s.meanLuminance : 0.0);
    md << "\nPremises of these statistics: one render per scene, with the scene's own seed and "
          "sampler; the largest sample is the largest luminance of one camera sample (before "
          "the pixel filter's weight) among the "
       << result.inputs.spp
       << " spp of every pixel, so it is one extreme draw, not an estimate with a spread: it "
          "grows with the sample count, and firefly ratios compare only at equal spp. No noise "
          "floor is given for it (one render has none to give); another seed or --spp shows "
          "how far it moves. A scene whose film clamps samples (film.max_component_value) "
          "caps it. No rejected sample means none among these samples, not that none can "
          "occur.\n";
    return md.str() + "\n";
}

}  // namespace

void writeStabilityReport(const StabilityResult& result, Report& report) {
    std::string md = "# Numerical stability\n\n" + modelsSection(result, report);
    if (!result.scenes.empty()) md += scenesSection(result);
    report.addSummary(md);
}

}  // namespace lamina::experiments
