// `lamina convergence SCENE -o DIR`: error against render time for every combination of
// integrator and render mode. Each combination renders progressively for the same time; after
// every pass the image is compared with a reference (relMSE with epsilon 1e-2, MSE, MAE).
// Writes convergence.csv, convergence.svg (log-log relMSE against seconds), summary.md (samples
// per second, final errors, the fitted slope of log relMSE against log seconds, which is -1 for
// an unbiased Monte Carlo estimator, and the time each needs to reach given error levels).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "lamina/cli/option_parsing.h"
#include "lamina/cli/svg_plot.h"
#include "lamina/core/error.h"
#include "lamina/render/image_metrics.h"
#include "lamina/render/renderer.h"

namespace lamina::cli {

namespace {

struct ConvergenceArgs {
    std::string scene;
    std::string output;
    std::string reference;
    std::string integrators = "path,light,bdpt";
    std::string modes = "rgb";
    std::string levels = "1e-2,1e-3";
    std::string resolution;
    std::string sampler;
    std::string referenceIntegrator = "path";
    double seconds = 10;
    double referenceSeconds = 0;
    int maxDepth = 0;
    int threads = 0;
};

/// Least-squares slope of log(relMSE) against log(seconds) over the passes after the first
/// tenth of the time (the first passes are dominated by start-up costs).
double fittedSlope(const std::vector<render::ErrorLog::Row>& rows) {
    if (rows.empty()) return NAN;
    const double from = 0.1 * rows.back().seconds;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& r : rows) {
        if (r.seconds < from || !(r.metrics.relmse > 0) || !(r.seconds > 0)) continue;
        const double x = std::log(r.seconds), y = std::log(r.metrics.relmse);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double den = n * sxx - sx * sx;
    if (n < 3 || !(std::abs(den) > 0)) return NAN;
    return (n * sxy - sx * sy) / den;
}

/// The first time relMSE reaches `level` (log-log interpolation between passes), or NAN.
double timeToReach(const std::vector<render::ErrorLog::Row>& rows, double level) {
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!(rows[i].metrics.relmse <= level)) continue;
        if (i == 0) return rows[0].seconds;
        const double x0 = std::log(rows[i - 1].seconds), x1 = std::log(rows[i].seconds);
        const double y0 = std::log(rows[i - 1].metrics.relmse),
                     y1 = std::log(rows[i].metrics.relmse);
        const double t = y1 != y0 ? (std::log(level) - y0) / (y1 - y0) : 1.0;
        return std::exp(x0 + std::clamp(t, 0.0, 1.0) * (x1 - x0));
    }
    return NAN;
}

std::string formatSeconds(double s, double budget) {
    char buf[32];
    if (std::isnan(s))
        std::snprintf(buf, sizeof buf, "> %.3g s", budget);
    else
        std::snprintf(buf, sizeof buf, "%.3g s", s);
    return buf;
}

struct Combination {
    std::string integrator, mode;
    render::ErrorLog log;
    double pathsPerSecond = 0;
    int spp = 0;
};

void run(const ConvergenceArgs& a) {
    const render::SceneDesc scene = render::loadScene(a.scene);
    const std::filesystem::path dir = a.output;
    std::filesystem::create_directories(dir);
    const auto integrators = splitList(a.integrators);
    const auto modes = splitList(a.modes);
    const auto levelNames = splitList(a.levels);
    std::vector<double> levels;
    for (const auto& l : levelNames) {
        try {
            levels.push_back(std::stod(l));
        } catch (const std::exception&) {
            throw CLI::ValidationError("--levels", "expected numbers, got \"" + l + "\"");
        }
    }
    for (const auto& i : integrators)
        integratorByName(i, "--integrators");
    for (const auto& m : modes)
        modeByName(m, "--modes");

    render::RenderOptions base;
    base.threads = a.threads;
    if (!a.sampler.empty())
        base.sampler = a.sampler == "independent" ? render::SamplerKind::Independent
                                                  : render::SamplerKind::Sobol;
    if (a.maxDepth > 0) base.maxDepth = a.maxDepth;
    if (!a.resolution.empty()) base.resolution = parseResolution(a.resolution);

    // One reference per mode (the two modes converge to slightly different images), unless
    // the user gives one.
    std::map<std::string, render::RgbImage> references;
    std::string referenceNote;
    if (!a.reference.empty()) {
        const render::RgbImage ref = render::readRgbImage(a.reference);
        for (const auto& m : modes)
            references[m] = ref;
        referenceNote = "reference: " + a.reference + " (given) for every mode";
    } else {
        const double refSeconds = a.referenceSeconds > 0 ? a.referenceSeconds : 20 * a.seconds;
        for (const auto& m : modes) {
            render::RenderOptions o = base;
            o.mode = modeByName(m, "--modes");
            o.integrator = integratorByName(a.referenceIntegrator, "--reference-integrator");
            o.sampler = render::SamplerKind::Sobol;
            o.seconds = refSeconds;
            // Its own seed: with the measured renders' seed, their first samples would be the
            // reference's and their error would look smaller than it is.
            o.seed = (scene.settings.seed + 0x5eed) & 0x7fffffffu;
            std::fprintf(stderr, "rendering the %s reference (%s integrator, %.0f s)...\n",
                         m.c_str(), a.referenceIntegrator.c_str(), refSeconds);
            const render::RenderResult r = render::renderScene(scene, o);
            references[m] = render::filmImage(*r.film);
            char note[256];
            std::snprintf(note, sizeof note,
                          "reference_%s.exr: %s integrator, %s mode, %d spp (Sobol, its own "
                          "seed) in %.1f s",
                          m.c_str(), a.referenceIntegrator.c_str(), m.c_str(), r.spp, r.seconds);
            render::ImageMetadata meta;
            meta.strings["integrator"] = a.referenceIntegrator;
            meta.strings["mode"] = m;
            meta.ints["spp"] = r.spp;
            render::writeExr(dir / ("reference_" + m + ".exr"), *r.film, false, meta);
            referenceNote += (referenceNote.empty() ? "" : "; ") + std::string(note);
        }
    }

    std::vector<Combination> results;
    for (const auto& m : modes)
        for (const auto& i : integrators) {
            render::RenderOptions o = base;
            o.mode = modeByName(m, "--modes");
            o.integrator = integratorByName(i, "--integrators");
            o.seconds = a.seconds;
            render::ErrorLog log(references[m]);
            std::fprintf(stderr, "%s, %s mode: %.3g s...\n", i.c_str(), m.c_str(), a.seconds);
            const render::RenderResult r =
                render::renderScene(scene, o, [&](const render::RenderProgress& p) {
                    log.record(p.seconds, p.sppDone, *p.film);
                });
            results.push_back({i, m, std::move(log), double(r.paths) / r.seconds, r.spp});
        }

    // CSV
    {
        std::ofstream csv(dir / "convergence.csv");
        csv << render::ErrorLog::csvHeader("integrator,mode");
        for (const Combination& c : results)
            csv << c.log.csvRows(c.integrator + "," + c.mode);
        if (!csv) throw InputError((dir / "convergence.csv").string() + ": cannot write");
    }
    // Plot
    SvgPlot plot("relMSE against render time: " + std::filesystem::path(a.scene).stem().string(),
                 "seconds", "relMSE (epsilon 1e-2)");
    plot.setLogX(true);
    plot.setLogY(true);
    for (const Combination& c : results) {
        SvgPlot::Series s;
        s.name = c.integrator + (modes.size() > 1 ? " " + c.mode : "");
        s.dashed = c.mode == "spectral";
        s.markers = true;
        for (const auto& r : c.log.rows()) {
            s.x.push_back(r.seconds);
            s.y.push_back(r.metrics.relmse);
        }
        plot.add(std::move(s));
    }
    plot.write(dir / "convergence.svg");

    // Summary
    std::ostringstream md;
    md << "# Convergence: " << a.scene << "\n\n"
       << referenceNote << ". Each combination rendered for " << a.seconds
       << " s; relMSE = mean((x - ref)^2 / (ref^2 + 1e-2)) over the RGB channels.\n\n"
       << "| integrator | mode | samples/s | spp | relMSE | MSE | slope |";
    for (const auto& l : levelNames)
        md << " time to relMSE " << l << " |";
    md << "\n|---|---|---|---|---|---|---|";
    for (std::size_t k = 0; k < levels.size(); ++k)
        md << "---|";
    md << "\n";
    for (const Combination& c : results) {
        const auto& rows = c.log.rows();
        const render::ErrorLog::Row last =
            rows.empty() ? render::ErrorLog::Row{0, 0, {}} : rows.back();
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %s | %.3g | %d | %.4g | %.4g | %.2f |",
                      c.integrator.c_str(), c.mode.c_str(), c.pathsPerSecond, c.spp,
                      last.metrics.relmse, last.metrics.mse, fittedSlope(rows));
        md << line;
        for (double l : levels)
            md << " " << formatSeconds(timeToReach(rows, l), a.seconds) << " |";
        md << "\n";
    }
    md << "\nThe slope is the least-squares fit of log relMSE against log seconds after the "
          "first tenth of the time: -1 for an unbiased estimator whose error is all variance; "
          "flatter once the reference's own error (or a bias) dominates.\n\n"
       << "![relMSE against time](convergence.svg)\n";
    std::ofstream(dir / "summary.md") << md.str();
    std::printf("%s", md.str().c_str());
}

}  // namespace

void registerConvergenceCommand(CLI::App& app) {
    auto a = std::make_shared<ConvergenceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convergence",
        "Error against render time for each integrator and mode: CSV, log-log plot, fitted "
        "slopes, time to reach error levels, a Markdown summary");
    cmd->add_option("scene", a->scene, "Scene file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", a->output, "Output directory")->required();
    cmd->add_option("--reference", a->reference,
                    "Reference EXR (default: rendered first, per mode, with the path integrator)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--integrators", a->integrators, "Comma-separated list")->capture_default_str();
    cmd->add_option("--modes", a->modes, "Comma-separated list of rgb, spectral")
        ->capture_default_str();
    cmd->add_option("--time", a->seconds, "Render time of each combination, seconds")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--reference-time", a->referenceSeconds,
                    "Render time of each rendered reference (default: 20 x --time)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--reference-integrator", a->referenceIntegrator,
                    "Integrator of the rendered references (bdpt for caustics)")
        ->check(CLI::IsMember({"path", "light", "bdpt"}))
        ->capture_default_str();
    cmd->add_option("--levels", a->levels, "relMSE levels for the time-to-error columns")
        ->capture_default_str();
    cmd->add_option("--resolution", a->resolution, "Image size WIDTHxHEIGHT (overrides)");
    cmd->add_option("--sampler", a->sampler,
                    "Sample generator of the measured renders (the reference always uses Sobol)")
        ->check(CLI::IsMember({"sobol", "independent"}));
    cmd->add_option("--max-depth", a->maxDepth, "Maximum scattering events per path")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--threads", a->threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::cli
