// The report of `lamina stability`: heat maps per model over (alpha, angle) and summary.md.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "lamina/experiments/stability.h"
#include "lamina/experiments/text_format.h"
#include "lamina/render/image_output.h"

namespace lamina::experiments {

namespace {

std::string cellText(const StabilityCell& t) {
    return formatText("%d | %d | %d | %d | %d | %.2g", t.nan, t.inf, t.negative, t.energyGain,
                      t.weightMismatch, t.worstFloatError);
}

void writeHeatMaps(const Report& report, const std::string& stem, const StabilityReport& r) {
    constexpr int kCell = 16;
    const int w = kCell * int(r.cosines.size()), h = kCell * int(r.alphas.size());
    std::vector<float> issues(std::size_t(w) * h * 3), error(std::size_t(w) * h * 3);
    for (std::size_t a = 0; a < r.alphas.size(); ++a)
        for (std::size_t c = 0; c < r.cosines.size(); ++c) {
            const StabilityCell& cell = r.at(a, c);
            // Issues: black none, red growing with log10(count). Float error: green up to
            // 1e-3, yellow to 1e-1, red beyond (log scale).
            const float t = cell.issues()
                                ? float(std::min(1.0, 0.3 + std::log10(double(cell.issues())) / 4))
                                : 0.0f;
            const double le = std::log10(std::max(cell.worstFloatError, 1e-8));
            const float e = float(std::clamp((le + 8) / 8, 0.0, 1.0));
            for (int y = 0; y < kCell; ++y)
                for (int x = 0; x < kCell; ++x) {
                    const std::size_t p = ((a * kCell + std::size_t(y)) * std::size_t(w) +
                                           c * kCell + std::size_t(x)) *
                                          3;
                    issues[p] = t;
                    error[p] = std::min(1.0f, 2 * e);
                    error[p + 1] = std::min(1.0f, 2 * (1 - e));
                }
        }
    render::writeRgb8(report.file(stem + "_issues.png"), w, h, issues);
    render::writeRgb8(report.file(stem + "_float_error.png"), w, h, error);
}

std::string modelsSection(const StabilityResult& result, const Report& report) {
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
    for (std::size_t i = 0; i < result.models.size(); ++i) {
        const AuditedModel& m = result.models[i];
        writeHeatMaps(report, "model" + std::to_string(i + 1), m.audit);
        md << "| `" << m.json << "` | " << cellText(m.audit.total()) << " |\n";
    }
    md << "\nHeat maps per model (`modelN_issues.png`: rows alpha, columns cos(theta_o) in the "
          "order above; black = no issue, red = more; `modelN_float_error.png`: green = float "
          "within 1e-8 of double, red = 1e-4 or worse).\n\n";
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
    return md.str() + "\n";
}

}  // namespace

void writeStabilityReport(const StabilityResult& result, Report& report) {
    std::string md = "# Numerical stability\n\n" + modelsSection(result, report);
    if (!result.scenes.empty()) md += scenesSection(result);
    report.addSummary(md);
}

}  // namespace lamina::experiments
