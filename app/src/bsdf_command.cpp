// `lamina bsdf`: inspect a material outside any scene (docs/bsdf.md, "lamina bsdf").
//   eval    JSON Lines {"wo": [x, y, z], "wi": [x, y, z]} on stdin -> {"f", "pdf", "pdf_reverse"}
//   sample  draws wi for one wo           -> one line per sample (JSON Lines or CSV)
//   albedo  directional albedo for cos theta_o = 0.05 ... 1, reflection and transmission
//   chi2    the chi-square goodness-of-fit test of sample() against pdf()
//   plot    figures: the lobe in the plane of incidence, and a map over the hemisphere
// Directions are in the local frame (z = normal) and are normalised by the tool.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "json_lines.h"
#include "lamina/bsdf/albedo_estimate.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/chi_square_test.h"
#include "lamina/core/error.h"
#include "lamina/core/json_reader.h"
#include "lamina/core/output_files.h"
#include "lamina/experiments/bsdf_plot.h"
#include "lamina/scene/rgl_bsdf_file.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct BsdfArgs {
    std::string material;
    std::string mode{render::kRenderModeNames.name(render::RenderModeKind::Rgb)};
    std::string wavelengths = "450,550,650";
    std::string transport = "radiance";
    std::string wo = "0,0,1";
    std::size_t count = 16;
    std::uint64_t seed = 0;
    std::string format = "jsonl";
    std::size_t samples = 1000000;
    std::string output = "lobe.png";
};

std::vector<double> parseNumbers(const std::string& text, const std::string& what) {
    std::vector<double> v;
    std::stringstream s(text);
    for (std::string item; std::getline(s, item, ',');) {
        char* end = nullptr;
        const double d = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(d))
            throw CLI::ValidationError(what,
                                       "expected comma-separated numbers, got \"" + text + "\"");
        v.push_back(d);
    }
    return v;
}

Vec3d parseDirection(const std::string& text, const std::string& what) {
    const auto v = parseNumbers(text, what);
    if (v.size() != 3) throw CLI::ValidationError(what, "expected x,y,z");
    const Vec3d d(v[0], v[1], v[2]);
    if (glm::length(d) == 0) throw CLI::ValidationError(what, "the direction is zero");
    return glm::normalize(d);
}

// The material as a figure names it: the @file, or the JSON literal cut short, and the mode.
std::string materialLabel(const BsdfArgs& a) {
    constexpr std::size_t kMaxChars = 48;
    std::string m = a.material;
    if (m.size() > kMaxChars) m = m.substr(0, kMaxChars) + "...";
    return m + " (" + a.mode + " mode" +
           (a.mode == render::kRenderModeNames.name(render::RenderModeKind::Spectral)
                ? ", " + a.wavelengths + " nm"
                : std::string()) +
           ")";
}

// `bsdf plot -o NAME.png`: the figures' files, checked before anything is computed.
experiments::BsdfPlotFiles plotFiles(const std::string& output) {
    if (std::filesystem::path(output).extension() != ".png")
        throw CLI::ValidationError("--output",
                                   "expected a .png file name (the figures are drawn as NAME.png "
                                   "and NAME-hemisphere.png, each also as PDF), got \"" +
                                       output + "\"");
    const experiments::BsdfPlotFiles files = experiments::bsdfPlotFiles(output);
    for (const auto& f : files.all())
        checkOutputFile(f);
    return files;
}

template <typename S>
class BsdfTool {
  public:
    BsdfTool(const BsdfArgs& a, std::unique_ptr<Bxdf<S>> bxdf, int channels)
        : a_(a),
          bxdf_(std::move(bxdf)),
          channels_(channels),
          mode_(*kTransportModeNames.find(a.transport)) {}

    void eval() const {
        std::string line;
        int lineNo = 0;
        while (std::getline(std::cin, line)) {
            ++lineNo;
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            const JsonSource source{"<stdin> line " + std::to_string(lineNo), "."};
            const Json j = parseJsonText(line, source);
            const JsonReader r(j, "", source);
            r.expectObject();
            const auto wo = r.requiredArray<3>("wo"), wi = r.requiredArray<3>("wi");
            r.finish();
            const Vec3d o = normalized(wo, r, "wo"), i = normalized(wi, r, "wi");
            const S f = bxdf_->eval(o, i, mode_);
            std::printf("{\"f\":%s,\"pdf\":%s,\"pdf_reverse\":%s}\n",
                        jsonArray(f, channels_).c_str(), jsonNumber(bxdf_->pdf(o, i)).c_str(),
                        jsonNumber(bxdf_->pdf(i, o)).c_str());
        }
    }

    void sample() const {
        const Vec3d wo = parseDirection(a_.wo, "--wo");
        Pcg32 rng(a_.seed);
        if (a_.format == "csv") {
            std::printf("wi_x,wi_y,wi_z,pdf,lobe");
            for (int c = 0; c < channels_; ++c)
                std::printf(",weight_%d", c);
            std::printf("\n");
        }
        for (std::size_t n = 0; n < a_.count; ++n) {
            // Drawn in the order uc, u.x, u.y (a constructor's arguments have no order of
            // evaluation): lamina.random_numbers(count, 3, seed) gives the same rows.
            const double uc = rng.nextDouble();
            const double ux = rng.nextDouble();
            const Vec2d u(ux, rng.nextDouble());
            const auto s = bxdf_->sample(wo, uc, u, mode_);
            if (a_.format == "csv") {
                if (!s) {
                    std::printf(",,,,none\n");
                    continue;
                }
                std::printf("%.9g,%.9g,%.9g,%.9g,%s", s->wi.x, s->wi.y, s->wi.z, s->pdf,
                            std::string(kLobeKindNames.name(LobeFlags(s->flags))).c_str());
                for (int c = 0; c < channels_; ++c)
                    std::printf(",%.9g", double(s->weight[c]));
                std::printf("\n");
            } else if (!s) {
                std::printf("{\"wi\":null}\n");
            } else {
                std::printf("{\"wi\":%s,\"weight\":%s,\"pdf\":%s,\"lobe\":\"%s\"}\n",
                            jsonVec(s->wi).c_str(), jsonArray(s->weight, channels_).c_str(),
                            jsonNumber(s->pdf).c_str(),
                            std::string(kLobeKindNames.name(LobeFlags(s->flags))).c_str());
            }
        }
    }

    void albedo() const {
        for (int step = 1; step <= 20; ++step) {
            const double c = 0.05 * step;
            const auto e =
                estimateAlbedo(*bxdf_, c, a_.samples, a_.seed + std::uint64_t(step), mode_);
            std::printf(
                "{\"cos_theta_o\":%.2f,\"reflection\":%s,\"transmission\":%s,\"stderr\":%s}\n", c,
                jsonArray(e.reflection, channels_).c_str(),
                jsonArray(e.transmission, channels_).c_str(),
                jsonArray(e.standardError, channels_).c_str());
        }
    }

    void chi2() const {
        const Vec3d wo = parseDirection(a_.wo, "--wo");
        ChiSquareConfig config;
        config.sampleCount = a_.samples;
        config.seed = a_.seed + 1;
        const ChiSquareResult r = runChiSquareTest(
            config,
            [&](Pcg32& rng) -> std::optional<Vec3d> {
                const double uc = rng.nextDouble();
                const double ux = rng.nextDouble();
                const Vec2d u(ux, rng.nextDouble());
                const auto s = bxdf_->sample(wo, uc, u, mode_);
                if (!s || s->isSpecular()) return std::nullopt;
                return s->wi;
            },
            [&](const Vec3d& wi) { return bxdf_->pdf(wo, wi); });
        std::printf(
            "chi-square: %s (p-value %.4g, statistic %.4g, %d degrees of freedom, "
            "significance %.3g, %zu valid samples, pdf integral %.4f)\n",
            r.passed ? "accepted" : "REJECTED", r.pValue, r.statistic, r.degreesOfFreedom, r.alpha,
            r.validSamples, r.pdfIntegral);
        if (!r.passed) std::printf("%s\n", r.message.c_str());
    }

    // The figures of experiments/bsdf_plot.h, of the channels' average (clamped at 0).
    void plot() const {
        const Vec3d wo = parseDirection(a_.wo, "--wo");
        const experiments::BsdfPlotFiles files = plotFiles(a_.output);
        const experiments::BsdfPlot plot = experiments::plotBsdf(
            [&](const Vec3d& wi) {
                return std::max(0.0, double(bxdf_->eval(wo, wi, mode_).average()));
            },
            wo, materialLabel(a_));
        const std::string note = experiments::writeBsdfPlot(plot, files);
        if (!note.empty()) std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
        std::fprintf(stderr,
                     "%s: f cos theta_i in the plane of incidence (the normal and (%.3g, %.3g, "
                     "0); peak %.4g); %s: over the upper hemisphere (peak %.4g)\n",
                     (files.directory / (files.plane + ".png")).c_str(), plot.tangent.x,
                     plot.tangent.y, plot.planePeak,
                     (files.directory / (files.hemisphere + ".png")).c_str(), plot.hemispherePeak);
    }

  private:
    static Vec3d normalized(const std::array<double, 3>& v, const JsonReader& r, const char* key) {
        const Vec3d d(v[0], v[1], v[2]);
        if (glm::length(d) == 0) r.failAt(key, "the direction is zero");
        return glm::normalize(d);
    }

    const BsdfArgs& a_;
    std::unique_ptr<Bxdf<S>> bxdf_;
    int channels_;
    TransportMode mode_;
};

template <typename Action>
void withTool(const BsdfArgs& a, Action action) {
    const MaterialDesc desc = parseMaterialArgument(a.material);
    render::loadMeasuredTables(desc);
    const auto mode = parseName(render::kRenderModeNames, a.mode, "mode", "--mode");
    if (mode == render::RenderModeKind::Polarised)
        throw CLI::ValidationError("--mode",
                                   "polarised renders scenes; `lamina bsdf` evaluates "
                                   "in rgb or spectral mode");
    if (mode == render::RenderModeKind::Spectral) {
        const auto nm = parseNumbers(a.wavelengths, "--wavelengths");
        if (nm.empty() || nm.size() > 4)
            throw CLI::ValidationError("--wavelengths", "expected 1 to 4 wavelengths in nm");
        std::array<double, 4> l{};
        for (std::size_t i = 0; i < 4; ++i) {
            l[i] = nm[std::min(i, nm.size() - 1)];
            if (l[i] < kLambdaMin || l[i] > kLambdaMax)
                throw CLI::ValidationError("--wavelengths",
                                           "wavelengths must lie in [360, 830] nm");
        }
        auto lambda = SampledWavelengths<double>::fixed(l);
        const SpectrumContext<SampledSpectrum<double>> context{lambda};
        BsdfTool<SampledSpectrum<double>> tool(a, buildBxdf(desc, context), int(nm.size()));
        action(tool);
    } else {
        const SpectrumContext<Rgb<double>> context;
        BsdfTool<Rgb<double>> tool(a, buildBxdf(desc, context), 3);
        action(tool);
    }
}

void addCommon(CLI::App* cmd, BsdfArgs& a) {
    cmd->add_option("material", a.material,
                    "Material: a JSON object literal or @file.json (docs/bsdf.md)")
        ->required();
    cmd->add_option("--mode", a.mode, "rgb or spectral")
        ->check(CLI::IsMember(render::kRenderModeNames.names()))
        ->capture_default_str();
    cmd->add_option("--wavelengths", a.wavelengths, "Spectral mode: 1-4 wavelengths in nm")
        ->capture_default_str();
    cmd->add_option("--transport", a.transport, "radiance or importance (adjoint)")
        ->check(CLI::IsMember(kTransportModeNames.names()))
        ->capture_default_str();
}

}  // namespace

void registerBsdfCommand(CLI::App& app) {
    auto a = std::make_shared<BsdfArgs>();
    CLI::App* bsdf =
        app.add_subcommand("bsdf", "Inspect a material: eval, sample, albedo, chi2, plot");
    bsdf->require_subcommand(1);

    CLI::App* eval = bsdf->add_subcommand("eval",
                                          "Read JSON Lines {\"wo\":[x,y,z],\"wi\":[x,y,z]} on "
                                          "stdin; print f*|cos_i|, pdf, pdf_reverse");
    addCommon(eval, *a);
    eval->callback([a] { withTool(*a, [](auto& t) { t.eval(); }); });

    CLI::App* sample = bsdf->add_subcommand("sample", "Draw directions wi for one wo");
    addCommon(sample, *a);
    sample->add_option("--wo", a->wo, "Outgoing direction x,y,z (local frame)")->required();
    sample->add_option("--count", a->count, "Number of samples")->check(CLI::Range(1, 100000000));
    sample->add_option("--seed", a->seed, "Random seed")->capture_default_str();
    sample->add_option("--format", a->format, "jsonl or csv")
        ->check(CLI::IsMember({"jsonl", "csv"}))
        ->capture_default_str();
    sample->callback([a] { withTool(*a, [](auto& t) { t.sample(); }); });

    CLI::App* albedo = bsdf->add_subcommand(
        "albedo", "Directional albedo (reflection, transmission) for cos theta_o = 0.05 ... 1");
    addCommon(albedo, *a);
    albedo->add_option("--samples", a->samples, "Samples per angle")
        ->check(CLI::Range(100, 1000000000))
        ->capture_default_str();
    albedo->add_option("--seed", a->seed, "Random seed")->capture_default_str();
    albedo->callback([a] { withTool(*a, [](auto& t) { t.albedo(); }); });

    CLI::App* chi2 = bsdf->add_subcommand("chi2", "Chi-square test of sample() against pdf()");
    addCommon(chi2, *a);
    chi2->add_option("--wo", a->wo, "Outgoing direction x,y,z (local frame)")->required();
    chi2->add_option("--samples", a->samples, "Number of samples")
        ->check(CLI::Range(1000, 1000000000))
        ->capture_default_str();
    chi2->add_option("--seed", a->seed, "Random seed")->capture_default_str();
    chi2->callback([a] { withTool(*a, [](auto& t) { t.chi2(); }); });

    CLI::App* plot = bsdf->add_subcommand(
        "plot", "Figures of the lobe (PNG and PDF): the plane of incidence, the upper hemisphere");
    addCommon(plot, *a);
    plot->add_option("--wo", a->wo, "Outgoing direction x,y,z (local frame)")->required();
    plot->add_option("-o,--output", a->output,
                     "Output NAME.png (also NAME.pdf, NAME-hemisphere.png and .pdf)")
        ->capture_default_str();
    plot->callback([a] { withTool(*a, [](auto& t) { t.plot(); }); });
}

}  // namespace lamina::app
