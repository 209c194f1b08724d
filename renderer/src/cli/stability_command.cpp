// `lamina stability [MATERIAL...] -o DIR [--scenes SCENE...]`: the extreme-input sweep of every
// model in float and double (stability_audit.h) over roughness alpha in {0, 1e-7, 1e-5, 1e-4,
// 1e-3, 0.01, 0.1, 0.5, 1} and cos(theta_o) in {1, 0.5, 0.1, 1e-2, 1e-4, 1e-6, 1e-8, 0, -0.5}:
// a table of NaN, Inf, negative values, energy gain, weight != eval / pdf and the worst
// float/double relative error, and per model two heat maps over (alpha, angle). With
// --scenes, renders stiff scenes (tiny bright lights, near-smooth glass, grazing views, high
// indices) and reports rejected samples and firefly statistics (the largest sample's
// luminance over the image's mean).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/stability_audit.h"
#include "lamina/core/error.h"
#include "lamina/render/image_output.h"
#include "lamina/render/renderer.h"
#include "lamina/spectral/color_space.h"

namespace lamina::cli {

namespace {

struct StabilityArgs {
    std::vector<std::string> materials;
    std::vector<std::string> scenes;
    std::string output;
    int spp = 64;
    int samples = 4096;
};

const std::vector<std::string>& defaultMaterials() {
    static const std::vector<std::string> m = {
        R"({"type":"conductor","material":"Au"})",
        R"({"type":"conductor","eta":0.5,"k":20})",
        R"({"type":"conductor","distribution":"beckmann","eta":0.4,"k":3})",
        R"({"type":"dielectric","ior":1.5})",
        R"({"type":"dielectric","ior":0.6666666666666666})",
        R"({"type":"dielectric","ior":4})",
        R"({"type":"standard","base_color":1})",
        R"({"type":"standard","base_color":[1,0.8,0.3],"metalness":1})",
        R"({"type":"standard","base_color":1,"transmission":0.7})",
        R"({"type":"lambert","reflectance":1})",
        R"({"type":"oren_nayar","reflectance":1,"roughness":1})",
        R"({"type":"burley","reflectance":1,"roughness":1})",
    };
    return m;
}

const std::vector<double> kAlphas = {0, 1e-7, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.5, 1};
const std::vector<double> kCosines = {1, 0.5, 0.1, 1e-2, 1e-4, 1e-6, 1e-8, 0, -0.5};

/// The material with its roughness replaced by alpha, or nullopt if it has none.
std::optional<MaterialDesc> withAlpha(const std::string& json, double alpha) {
    nlohmann::json j = nlohmann::json::parse(json);
    j.erase("roughness");
    j["alpha"] = alpha;
    try {
        return parseMaterialArgument(j.dump());
    } catch (const InputError&) {
        return std::nullopt;
    }
}

std::string cellText(const StabilityCell& t) {
    char line[256];
    std::snprintf(line, sizeof line, "%d | %d | %d | %d | %d | %.2g", t.nan, t.inf, t.negative,
                  t.energyGain, t.weightMismatch, t.worstFloatError);
    return line;
}

void writeHeatMaps(const std::filesystem::path& dir, const std::string& stem,
                   const StabilityReport& r) {
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
    render::writeRgb8(dir / (stem + "_issues.png"), w, h, issues);
    render::writeRgb8(dir / (stem + "_float_error.png"), w, h, error);
}

std::string auditMaterials(const std::vector<std::string>& materials,
                           const std::filesystem::path& dir, int samples) {
    std::ostringstream md;
    md << "## BSDF models on extreme inputs\n\nalpha in {";
    for (double a : kAlphas)
        md << a << (a == kAlphas.back() ? "" : ", ");
    md << "} (models without a roughness: one row), cos(theta_o) in {";
    for (double c : kCosines)
        md << c << (c == kCosines.back() ? "" : ", ");
    md << "}; per cell " << samples
       << " samples and 71 evaluation directions in both transport modes, float and double.\n\n"
          "| model | NaN | Inf | negative | energy gain | weight != eval/pdf | worst float/double "
          "error |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const std::string& json = materials[i];
        parseMaterialArgument(json);  // a clear error for a bad material
        const bool rough = withAlpha(json, 0.5).has_value();
        StabilityModel model;
        model.makeDouble = [&](double alpha) {
            const MaterialDesc m = rough ? *withAlpha(json, alpha) : parseMaterialArgument(json);
            return buildBxdf(m, SpectrumContext<Rgb<double>>{});
        };
        model.makeFloat = [&](double alpha) {
            const MaterialDesc m = rough ? *withAlpha(json, alpha) : parseMaterialArgument(json);
            return buildBxdf(m, SpectrumContext<Rgb<float>>{});
        };
        const StabilityReport r = auditStability(model, rough ? kAlphas : std::vector<double>{0.0},
                                                 kCosines, 64, samples);
        const std::string stem = "model" + std::to_string(i + 1);
        writeHeatMaps(dir, stem, r);
        md << "| `" << json << "` | " << cellText(r.total()) << " |\n";
        std::fprintf(stderr, "audited %s\n", json.c_str());
    }
    md << "\nHeat maps per model (`modelN_issues.png`: rows alpha, columns cos(theta_o) in the "
          "order above; black = no issue, red = more; `modelN_float_error.png`: green = float "
          "within 1e-8 of double, red = 1e-4 or worse).\n\n";
    return md.str();
}

std::string renderStressScenes(const std::vector<std::string>& scenes, int spp) {
    std::ostringstream md;
    md << "## Stiff scenes\n\n"
       << spp
       << " spp each, path integrator, RGB mode. A rejected sample had a NaN, Inf or negative "
          "value and was not added; the firefly ratio is the largest sample's luminance over "
          "the image's mean luminance.\n\n"
          "| scene | rejected samples | largest sample | image mean | firefly ratio |\n"
          "|---|---|---|---|---|\n";
    for (const std::string& s : scenes) {
        const render::SceneDesc scene = render::loadScene(s);
        render::RenderOptions o;
        o.spp = spp;
        const render::RenderResult r = render::renderScene(scene, o);
        double mean = 0;
        for (int y = 0; y < r.film->height(); ++y)
            for (int x = 0; x < r.film->width(); ++x)
                mean += luminance(r.film->pixel(x, y));
        mean /= double(r.film->width()) * r.film->height();
        const double largest = r.film->largestSampleLuminance();
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %llu | %.4g | %.4g | %.3g |\n",
                      std::filesystem::path(s).filename().string().c_str(),
                      static_cast<unsigned long long>(r.film->rejectedSamples()), largest, mean,
                      mean > 0 ? largest / mean : 0.0);
        md << line;
        std::fprintf(stderr, "rendered %s\n", s.c_str());
    }
    return md.str() + "\n";
}

void run(const StabilityArgs& a) {
    const std::filesystem::path dir = a.output;
    std::filesystem::create_directories(dir);
    const std::vector<std::string>& materials =
        a.materials.empty() ? defaultMaterials() : a.materials;
    std::string md = "# Numerical stability\n\n" + auditMaterials(materials, dir, a.samples);
    if (!a.scenes.empty()) md += renderStressScenes(a.scenes, a.spp);
    std::ofstream(dir / "summary.md") << md;
    std::printf("%s", md.c_str());
}

}  // namespace

void registerStabilityCommand(CLI::App& app) {
    auto a = std::make_shared<StabilityArgs>();
    CLI::App* cmd = app.add_subcommand(
        "stability",
        "Extreme-input sweep of BSDF models in float and double (NaN, Inf, negative, energy "
        "gain, weight != eval/pdf, float error) and firefly statistics of stiff scenes");
    cmd->add_option("materials", a->materials,
                    "Materials as JSON (default: a conductor, dielectric, standard and diffuse "
                    "set); roughness is replaced by the sweep's alpha");
    cmd->add_option("-o,--output", a->output, "Output directory")->required();
    cmd->add_option("--scenes", a->scenes, "Stiff scenes to render (e.g. scenes/stress/*.json)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--spp", a->spp, "Samples per pixel of the scene renders")
        ->check(CLI::Range(1, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--samples", a->samples, "BSDF samples per (alpha, angle) cell")
        ->check(CLI::Range(16, 1 << 24))
        ->capture_default_str();
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::cli
