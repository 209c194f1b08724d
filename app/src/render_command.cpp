// `lamina render SCENE`: renders a scene file to OpenEXR (and optionally a PNG preview).
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "declared_options.h"
#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/core/printable.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/output/image_output.h"
#include "lamina/output/render_metadata.h"
#include "lamina/output/shard_file.h"
#include "lamina/output/strategy_files.h"
#include "lamina/render/renderer.h"
#include "lamina/version.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

// What the command line alone reads: the files it writes beside the image and how it reports.
struct RenderFiles {
    std::string scene;
    std::string output;
    std::string reference;
    std::string errorLog;
    std::string strategies;
    bool preview = false;
    double exposure = 0;
    bool quiet = false;

    explicit RenderFiles(const experiments::OptionValues& v)
        : scene(*v.text("scene")),
          output(v.text("output").value_or("")),
          reference(v.text("reference").value_or("")),
          errorLog(v.text("error-log").value_or("")),
          strategies(v.text("strategies").value_or("")),
          preview(v.flag("preview")),
          exposure(*v.number("exposure")),
          quiet(v.flag("quiet")) {}
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

// Every file the render will write, checked before it starts (the scene and the reference
// are inputs none of them may replace).
void checkOutputs(const RenderFiles& a, const std::filesystem::path& output,
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

/// The shard in `output` if it is the partial output of this same command (a requeued or
/// restarted array task: the same command line, scene files and sample range), to resume from
/// instead of overwriting; nothing otherwise (another file is overwritten as before).
std::optional<render::ShardFile> partialShardToResume(const std::filesystem::path& output,
                                                      const render::SceneDesc& scene,
                                                      const render::SampleRange& range) {
    if (!std::filesystem::exists(output)) return std::nullopt;
    try {
        render::ShardFile shard = render::readShardExr(output);
        const auto commandLine = shard.metadata.strings.find("command_line");
        if (!shard.partial || shard.samplesDone < 1 || shard.samplesDone >= range.count ||
            shard.requested.first != range.first || shard.requested.count != range.count ||
            shard.sceneHash != render::sceneHash(scene) ||
            commandLine == shard.metadata.strings.end() ||
            commandLine->second != render::processCommandLine())
            return std::nullopt;
        return shard;
    } catch (const InputError&) {
        return std::nullopt;  // not a shard of lamina's, or damaged: rendered anew
    }
}

void runRender(const experiments::OptionValues& values) {
    const RenderFiles a(values);
    const render::SceneDesc scene = render::loadScene(a.scene);
    std::filesystem::path output = a.output;
    if (output.empty()) output = std::filesystem::path(a.scene).stem().string() + ".exr";
    const std::filesystem::path preview = std::filesystem::path(output).replace_extension(".png");
    checkOutputs(a, output, preview);

    render::RenderOptions o = experiments::renderOptionsFrom(values);
    o.strategies = !a.strategies.empty();
    if (o.strategies &&
        o.integrator.value_or(scene.settings.integrator) != render::IntegratorKind::Bdpt)
        throw CLI::ValidationError("--strategies", "needs the bdpt integrator");
    if (const auto samples = values.text("samples")) o.samples = parseSampleRange(*samples);
    if (const auto crop = values.text("crop")) o.crop = parsePixelBounds(*crop);
    const bool shard = o.samples || o.crop;
    if (shard && !a.reference.empty())
        throw CLI::ValidationError("--error-log",
                                   "measures whole renders: not with --samples "
                                   "or --crop (merge the shards, then compare)");

    if (!a.reference.empty() && scene.film.crop && !o.crop && !o.resolution)
        throw InputError(a.scene +
                         ": film.crop: --error-log measures whole renders (remove the "
                         "crop)");
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

    // A restarted shard keeps the samples its partial output holds and renders the rest of
    // its range (docs/distributed.md, "Requeued shards").
    std::optional<render::ShardFile> earlier;
    if (o.samples) earlier = partialShardToResume(output, scene, *o.samples);
    const render::RenderOptions asked = o;
    if (earlier) {
        o.samples = render::SampleRange{o.samples->first + earlier->samplesDone,
                                        o.samples->count - earlier->samplesDone};
        // A time budget is the shard's whole: what the interrupted run spent counts.
        if (o.seconds) o.seconds = std::max(*o.seconds - earlier->seconds, 1e-3);
        std::fprintf(stderr, "lamina: resuming %s: %d of its %d samples kept, from sample %d\n",
                     output.string().c_str(), earlier->samplesDone, asked.samples->count,
                     o.samples->first);
    }

    ProgressPrinter printer(a.quiet);
    const RenderInterruption interruption;  // until the files are written
    render::RenderResult r = render::renderScene(scene, o, [&](const render::RenderProgress& p) {
        if (errors) errors->record(p.seconds, p.sppDone, *p.film);
        printer(p);
    });
    printer.finish();
    for (const std::string& w : r.warnings)
        std::fprintf(stderr, "lamina: warning: %s\n", w.c_str());

    if (earlier) {
        if (render::shardSettings(scene, o, r) != earlier->settings)
            throw InputError(output.string() +
                             ": lamina:shard_settings: the partial shard was "
                             "rendered with other settings than this command's");
        render::addShardSums(*r.film, *earlier);
        r.firstSample = asked.samples->first;
        r.spp += earlier->samplesDone;
        r.seconds += earlier->seconds;
        o = asked;
    }
    render::ImageMetadata meta =
        render::renderMetadata(scene, o, r, {LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT});
    if (shard) {
        render::addShardMetadata(meta, scene, o, r);
        render::writeShardExr(output, *r.film, meta);
    } else {
        render::writeExr(output, *r.film, o.aovs, meta);
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
    if (r.strategies)
        render::writeStrategyImages(a.strategies, *r.strategies, *r.film, r.spp, meta);
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
    const experiments::CommandDecl& command = experiments::commandDeclaration("render");
    CLI::App* cmd = app.add_subcommand(command.name, command.help);
    auto options = std::make_shared<DeclaredOptions>(*cmd, command);
    cmd->callback([options] { runRender(options->values()); });
}

}  // namespace lamina::app
