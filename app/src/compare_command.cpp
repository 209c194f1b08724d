// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour picture of |A - B|.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/experiments/image_metrics.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct CompareArgs {
    std::string a, b;
    std::string metrics = experiments::kMetricNames.list(",");
    std::string diff;
    double diffScale = 0;  ///< 0: the largest difference
};

void run(const CompareArgs& args) {
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
    std::stringstream list(args.metrics);
    for (std::string name; std::getline(list, name, ',');) {
        const auto metric = parseName(experiments::kMetricNames, name, "metric", "--metric");
        std::printf("%s %.9g\n", name.c_str(), experiments::metricValue(m, metric));
    }
    if (!args.diff.empty()) {
        const double scale = args.diffScale > 0 ? args.diffScale : m.max;
        experiments::writeDifferenceImage(args.diff, a, b, scale);
        // Beside the metrics, in their "name value" form: the difference shown white.
        std::printf("diff_scale %.9g\n", scale);
    }
}

}  // namespace

void registerCompareCommand(CLI::App& app) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* cmd = app.add_subcommand(
        "compare", "Error metrics of an image against a reference (relMSE epsilon 1e-2)");
    cmd->add_option("image", a->a, "Image to measure (EXR or any OpenImageIO format)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("reference", a->b, "Reference image")->required()->check(CLI::ExistingFile);
    cmd->add_option("--metric", a->metrics, "Comma-separated: " + experiments::kMetricNames.list())
        ->capture_default_str();
    cmd->add_option("--diff", a->diff,
                    "Write a false-colour PNG of |image - reference| and beside it an SVG "
                    "figure with its colour bar");
    cmd->add_option("--diff-scale", a->diffScale,
                    "The difference shown white in --diff (default: the largest)")
        ->check(CLI::PositiveNumber);
    cmd->callback([a] { runInterruptible("compare", [&] { run(*a); }); });
}

}  // namespace lamina::app
