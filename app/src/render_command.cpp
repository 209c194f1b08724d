// `lamina render SCENE`: renders a scene file to OpenEXR (and optionally a PNG preview).
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/core/printable.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/output/image_output.h"
#include "lamina/output/render_metadata.h"
#include "lamina/render/renderer.h"
#include "lamina/output/shard_file.h"
#include "lamina/version.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::string mode{render::kRenderModeNames.name(render::RenderModeKind::Rgb)};
    std::string integrator;
    std::string mis;
    std::string strategies;
    std::string reference;
    std::string errorLog;
    std::string sampler;
    std::string lightSelection;
    std::string samples;
    std::string crop;
    int spp = 0;
    double seconds = 0;
    long long seed = -1;
    RenderOverrides overrides;
    bool preview = false;
    double exposure = 0;
    bool aovs = false;
    bool quiet = false;
};

class ProgressPrinter {
  public:
    explicit ProgressPrinter(bool quiet) : quiet_(quiet), terminal_(::isatty(STDERR_FILENO)) {}

    void operator()(const render::RenderProgress& p) {
        if (quiet_) return;
        const double eta = p.fraction > 0 ? p.seconds * (1 - p.fraction) / p.fraction : 0;
        if (terminal_) {
            const int width = 40, filled = int(p.fraction * width + 0.5);
            std::fprintf(stderr, "\r[%s%s] %5.1f%%  %d spp  %.1fs  ETA %.1fs ",
                         std::string(std::size_t(filled), '#').c_str(),
                         std::string(std::size_t(width - filled), '.').c_str(), 100 * p.fraction,
                         p.sppDone, p.seconds, eta);
            std::fflush(stderr);
            lastLineOpen_ = true;
        } else {
            const int decile = int(p.fraction * 10);
            if (decile <= lastDecile_) return;
            lastDecile_ = decile;
            std::fprintf(stderr, "progress: %3.0f%% (%d spp, %.1f s, ETA %.1f s)\n",
                         100 * p.fraction, p.sppDone, p.seconds, eta);
        }
    }
    void finish() {
        if (lastLineOpen_) std::fprintf(stderr, "\n");
    }

  private:
    bool quiet_, terminal_;
    bool lastLineOpen_ = false;
    int lastDecile_ = -1;
};

// One EXR per strategy: s<S>_t<T>_weighted.exr (its share of the image) and
// s<S>_t<T>_unweighted.exr (what the strategy alone estimates).
void writeStrategyImages(const std::string& directory, const render::StrategyImages& images,
                         const render::Film& like, int spp, const render::ImageMetadata& meta) {
    std::filesystem::create_directories(directory);
    const double particles = double(images.width()) * images.height() * spp;
    for (std::size_t i = 0; i < images.strategies().size(); ++i) {
        const auto [s, t] = images.strategies()[i];
        for (const bool weighted : {true, false}) {
            render::Film film(images.width(), images.height(), like.space());
            const auto pixels = images.image(int(i), weighted, particles);
            for (int y = 0; y < film.height(); ++y)
                for (int x = 0; x < film.width(); ++x)
                    film.addSample(x, y, pixels[std::size_t(y) * film.width() + x], 1.0);
            render::ImageMetadata m = meta;
            m.ints["s"] = s;
            m.ints["t"] = t;
            m.ints["mis_weighted"] = weighted ? 1 : 0;
            const std::string name = "s" + std::to_string(s) + "_t" + std::to_string(t) +
                                     (weighted ? "_weighted.exr" : "_unweighted.exr");
            render::writeExr(std::filesystem::path(directory) / name, film, false, m);
        }
    }
}

// Every file the render will write, checked before it starts (the scene and the reference
// are inputs none of them may replace).
void checkOutputs(const RenderArgs& a, const std::filesystem::path& output,
                  const std::filesystem::path& preview) {
    if (output.extension() != ".exr")
        throw CLI::ValidationError(
            "--output", escapeControl(output.string()) + ": the output is OpenEXR: name it .exr");
    std::vector<std::filesystem::path> inputs = {a.scene};
    if (!a.reference.empty()) inputs.emplace_back(a.reference);
    render::checkOutputPath(output, inputs);
    if (a.preview) render::checkOutputPath(preview, inputs);
    if (!a.errorLog.empty()) checkOutputFile(a.errorLog, inputs);
    if (!a.strategies.empty()) checkOutputDirectory(a.strategies);
}

void runRender(const RenderArgs& a) {
    const render::SceneDesc scene = render::loadScene(a.scene);
    std::filesystem::path output = a.output;
    if (output.empty()) output = std::filesystem::path(a.scene).stem().string() + ".exr";
    const std::filesystem::path preview = std::filesystem::path(output).replace_extension(".png");
    checkOutputs(a, output, preview);

    render::RenderOptions o;
    o.mode = parseName(render::kRenderModeNames, a.mode, "mode", "--mode");
    if (a.spp > 0) o.spp = a.spp;
    if (a.seconds > 0) o.seconds = a.seconds;
    if (a.seed >= 0) o.seed = std::uint64_t(a.seed);
    if (!a.sampler.empty())
        o.sampler = parseName(render::kSamplerNames, a.sampler, "sampler", "--sampler");
    if (!a.lightSelection.empty())
        o.lightSelection = parseName(render::kLightSelectionNames, a.lightSelection,
                                     "light selection", "--light-selection");
    if (!a.integrator.empty())
        o.integrator =
            parseName(render::kIntegratorNames, a.integrator, "integrator", "--integrator");
    if (!a.mis.empty())
        o.mis = parseName(render::kMisHeuristicNames, a.mis, "MIS heuristic", "--mis");
    o.strategies = !a.strategies.empty();
    if (o.strategies &&
        o.integrator.value_or(scene.settings.integrator) != render::IntegratorKind::Bdpt)
        throw CLI::ValidationError("--strategies", "needs the bdpt integrator");
    a.overrides.applyTo(o);
    o.aovs = a.aovs;
    if (!a.samples.empty()) o.samples = parseSampleRange(a.samples);
    if (!a.crop.empty()) o.crop = parsePixelBounds(a.crop);
    const bool shard = o.samples || o.crop;
    if (shard && !a.reference.empty())
        throw CLI::ValidationError("--error-log",
                                   "measures whole renders: not with --samples "
                                   "or --crop (merge the shards, then compare)");

    std::optional<experiments::ErrorLog> errors;
    if (!a.reference.empty()) errors.emplace(render::readLinearRgbImage(a.reference));
    if (errors) {
        const int w = o.resolution ? o.resolution->first : scene.film.width;
        const int h = o.resolution ? o.resolution->second : scene.film.height;
        if (errors->reference().width != w || errors->reference().height != h)
            throw InputError(a.reference + " is " + std::to_string(errors->reference().width) +
                             "x" + std::to_string(errors->reference().height) +
                             " but the render is " + std::to_string(w) + "x" + std::to_string(h));
    }

    ProgressPrinter printer(a.quiet);
    const RenderInterruption interruption;  // until the files are written
    const render::RenderResult r =
        render::renderScene(scene, o, [&](const render::RenderProgress& p) {
            if (errors) errors->record(p.seconds, p.sppDone, *p.film);
            printer(p);
        });
    printer.finish();

    render::ImageMetadata meta =
        render::renderMetadata(scene, o, r, {LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT});
    if (shard) {
        render::addShardMetadata(meta, scene, o, r);
        render::writeShardExr(output, *r.film, meta);
    } else {
        render::writeExr(output, *r.film, a.aovs, meta);
    }
    if (errors) {
        TemporaryFile tmp(a.errorLog);
        {
            std::ofstream csv(tmp.path());
            csv << experiments::ErrorLog::csvHeader() << errors->csvRows();
            if (!csv) throw InputError(a.errorLog + ": cannot write");
        }
        tmp.commit();
    }
    if (r.strategies) writeStrategyImages(a.strategies, *r.strategies, *r.film, r.spp, meta);
    if (a.preview) render::writePngPreview(preview, *r.film, a.exposure);

    if (!a.quiet) {
        std::fprintf(
            stderr,
            "%s: %dx%d, %d spp, %s, %.2f s, %.3g paths/s, %.3g rays/s, "
            "%llu rejected samples%s\n",
            output.string().c_str(), r.film->width(), r.film->height(), r.spp,
            (r.modeName + " mode, " +
             std::string(render::kIntegratorNames.name(r.settings.integrator)) + " integrator")
                .c_str(),
            r.seconds, double(r.paths) / r.seconds, double(r.rays) / r.seconds,
            static_cast<unsigned long long>(r.film->rejectedSamples()),
            r.partial ? " (interrupted: partial image)" : "");
        if (a.preview) std::fprintf(stderr, "preview: %s\n", preview.string().c_str());
    }
    if (interruption.signal() != 0) throw CLI::RuntimeError(interruption.exitStatus());
}

}  // namespace

void registerRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file to OpenEXR");
    cmd->add_option("scene", args->scene, "Scene file (JSON, see docs/scene-format.md)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output,
                    "Output EXR (default: the scene's name in the current directory)");
    cmd->add_option("--mode", args->mode, "Render mode")
        ->check(CLI::IsMember(render::kRenderModeNames.names()))
        ->capture_default_str();
    cmd->add_option("--integrator", args->integrator,
                    "Light transport algorithm: path, light or bdpt (overrides the scene's)")
        ->check(CLI::IsMember(render::kIntegratorNames.names()));
    cmd->add_option("--mis", args->mis, "BDPT's MIS heuristic (overrides the scene's)")
        ->check(CLI::IsMember(render::kMisHeuristicNames.names()));
    auto* reference =
        cmd->add_option("--reference", args->reference, "Reference image for --error-log")
            ->check(CLI::ExistingFile);
    cmd->add_option("--error-log", args->errorLog,
                    "CSV of seconds, spp, MSE, relMSE, MAE against --reference after every pass")
        ->needs(reference);
    reference->needs(cmd->get_option("--error-log"));
    cmd->add_option("--strategies", args->strategies,
                    "bdpt: also write one EXR per (s, t) strategy, MIS-weighted and "
                    "unweighted, path depth <= 4, into this directory");
    auto* spp = cmd->add_option("--spp", args->spp, "Samples per pixel (overrides the scene's)")
                    ->check(CLI::Range(1, render::kMaxSppOverride));
    cmd->add_option("--time", args->seconds, "Render progressive passes for this many seconds")
        ->check(positiveNumber("seconds"))
        ->excludes(spp);
    cmd->add_option("--samples", args->samples,
                    "FIRST:COUNT: render sample indices [FIRST, FIRST+COUNT) of every pixel "
                    "into a shard EXR for `lamina merge` (with --time: at most COUNT)")
        ->excludes(spp);
    cmd->add_option("--crop", args->crop,
                    "X0,X1,Y0,Y1: render pixels [X0,X1) x [Y0,Y1) of the film into a shard EXR "
                    "for `lamina merge`");
    cmd->add_option("--seed", args->seed, "Random seed (overrides the scene's)")
        ->check(CLI::Range(0LL, render::kMaxSeedOverride));
    addThreadsOption(cmd, args->overrides);
    addResolutionOption(cmd, args->overrides);
    addMaxDepthOption(cmd, args->overrides);
    cmd->add_option("--sampler", args->sampler, "Sample generator")
        ->check(CLI::IsMember(render::kSamplerNames.names()));
    cmd->add_option("--light-selection", args->lightSelection,
                    "How next-event estimation picks a light (overrides the scene's)")
        ->check(CLI::IsMember(render::kLightSelectionNames.names()));
    cmd->add_flag("--preview", args->preview, "Also write a PNG preview beside the EXR");
    cmd->add_option("--exposure", args->exposure, "Exposure of the preview in stops")
        ->capture_default_str();
    cmd->add_flag("--aovs", args->aovs,
                  "Add AOV layers: Albedo.RGB, N.XYZ (shading normal), Z (depth), Variance.Y");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr");
    cmd->callback([args] { runRender(*args); });
}

}  // namespace lamina::app
