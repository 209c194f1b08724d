// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour map of |A - B| (a figure of the figure module: NAME.png,
// NAME.pdf, with its data NAME.figure.json and NAME.f32; docs/figures.md) and a page with a
// viewer of the two images (--html; python/lamina/report_page.py).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "declared_options.h"
#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/experiments/figure_drawing.h"
#include "lamina/experiments/figure_spec.h"
#include "lamina/experiments/image_metrics.h"

namespace lamina::app {

namespace {

struct CompareArgs {
    std::string a, b;
    std::vector<experiments::Metric> metrics;
    std::string diff, html;
    double diffScale = 0;  ///< 0: the 99th percentile of the difference

    explicit CompareArgs(const experiments::OptionValues& v)
        : a(*v.text("image")),
          b(*v.text("reference")),
          metrics(v.choices(experiments::kMetricNames, "metric")),
          diff(v.text("diff").value_or("")),
          html(v.text("html").value_or("")),
          diffScale(v.number("diff-scale").value_or(0)) {}
};

/// The map of |a - b| as a figure beside `png` (its stem): the scale from the difference's
/// 99th percentile, or fixed by --diff-scale. Returns the scale.
double writeDifference(const CompareArgs& args, const render::RgbImage& a,
                       const render::RgbImage& b) {
    experiments::MapFigure map = experiments::differenceFigure(
        a, b,
        "|" + std::filesystem::path(args.a).filename().string() + " - " +
            std::filesystem::path(args.b).filename().string() + "| of each pixel");
    double scale = experiments::percentileOf(map.values, map.percentile);
    if (args.diffScale > 0) {
        scale = args.diffScale;
        map.upper = scale;
        map.clipReason = "The scale was fixed by --diff-scale.";
    }
    if (std::filesystem::path(args.diff).extension() != ".png") {
        // Another format (TIFF, EXR, ...): the false-colour image alone, as lamina writes it.
        experiments::writeDifferenceImage(args.diff, a, b, scale);
        return scale;
    }
    const std::filesystem::path stem = std::filesystem::path(args.diff).replace_extension();
    const std::filesystem::path directory =
        stem.has_parent_path() ? stem.parent_path() : std::filesystem::path(".");
    experiments::writeFigureSpec(directory, stem.filename().string(), map);
    const std::string note =
        experiments::drawFigures(directory / (stem.filename().string() + ".figure.json"));
    if (!note.empty()) std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
    return scale;
}

/// The viewer page of a and b at args.html: the pair's spec and data in a temporary directory
/// beside it, which goes when the page is written (or not).
void writeViewer(const CompareArgs& args, const render::RgbImage& a, const render::RgbImage& b) {
    const std::filesystem::path page = args.html;
    const std::filesystem::path work =
        (page.has_parent_path() ? page.parent_path() : std::filesystem::path(".")) /
        (page.filename().string() + ".pair.tmp");
    const std::string labelA = std::filesystem::path(args.a).filename().string();
    const std::string labelB = std::filesystem::path(args.b).filename().string();
    const experiments::ImagePair pair =
        experiments::imagePair(a, labelA, b, labelB, labelA + " against " + labelB);
    struct RemovedAtTheEnd {
        std::filesystem::path path;
        ~RemovedAtTheEnd() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    } cleanup{work};
    std::filesystem::create_directories(work);
    experiments::writeImagePairSpec(work, "pair", pair);
    const std::string note = experiments::writePairPage(work / "pair.pair.json", page);
    if (!note.empty()) std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
}

void run(const CompareArgs& args) {
    if (!args.diff.empty()) checkOutputFile(args.diff, {args.a, args.b});
    if (!args.html.empty()) checkOutputFile(args.html, {args.a, args.b});
    const render::RgbImage a = render::readRgbImage(args.a);
    const render::RgbImage b = render::readRgbImage(args.b);
    // Both sides are linear after reading; a display image (sRGB, tone-mapped and clipped)
    // against a linear one would measure the tone mapping, not the render.
    if (a.displayReferred != b.displayReferred) {
        const std::string& display = a.displayReferred ? args.a : args.b;
        const std::string& linear = a.displayReferred ? args.b : args.a;
        throw InputError(display +
                         ": an sRGB-encoded display image (tone-mapped and clipped to "
                         "[0, 1]) cannot be compared with the linear image " +
                         linear + ": compare the EXRs, or two display images");
    }
    if (a.width != b.width || a.height != b.height)
        throw InputError(args.a + " is " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " but " + args.b + " is " +
                         std::to_string(b.width) + "x" + std::to_string(b.height));
    const experiments::ImageMetrics m = experiments::compareImages(a, b);
    experiments::requireComparedValues(m, a, args.a, b, args.b);
    if (const std::string note = experiments::nonFiniteNote(m); !note.empty())
        std::fprintf(stderr, "lamina: warning: %s\n", note.c_str());
    for (const experiments::Metric metric : args.metrics)
        std::printf("%s %.9g\n", std::string(experiments::kMetricNames.name(metric)).c_str(),
                    experiments::metricValue(m, metric));
    if (!args.diff.empty()) {
        const double scale = writeDifference(args, a, b);
        // Beside the metrics, in their "name value" form: the top of the colour scale.
        std::printf("diff_scale %.9g\n", scale);
    }
    if (!args.html.empty()) writeViewer(args, a, b);
}

}  // namespace

void registerCompareCommand(CLI::App& app) {
    const experiments::CommandDecl& command = experiments::commandDeclaration("compare");
    CLI::App* cmd = app.add_subcommand(command.name, command.help);
    auto options = std::make_shared<DeclaredOptions>(*cmd, command);
    cmd->callback([options] {
        const CompareArgs args(options->values());
        runInterruptible("compare", [&] { run(args); });
    });
}

}  // namespace lamina::app
