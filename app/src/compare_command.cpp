// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour picture of |A - B|.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "declared_options.h"
#include "interruption.h"
#include "lamina/core/error.h"
#include "lamina/experiments/image_metrics.h"

namespace lamina::app {

namespace {

struct CompareArgs {
    std::string a, b;
    std::vector<experiments::Metric> metrics;
    std::string diff;
    double diffScale = 0;  ///< 0: the largest difference

    explicit CompareArgs(const experiments::OptionValues& v)
        : a(*v.text("image")),
          b(*v.text("reference")),
          metrics(v.choices(experiments::kMetricNames, "metric")),
          diff(v.text("diff").value_or("")),
          diffScale(v.number("diff-scale").value_or(0)) {}
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
    experiments::requireComparedValues(m, a, args.a, b, args.b);
    if (const std::string note = experiments::nonFiniteNote(m); !note.empty())
        std::fprintf(stderr, "lamina: warning: %s\n", note.c_str());
    for (const experiments::Metric metric : args.metrics)
        std::printf("%s %.9g\n", std::string(experiments::kMetricNames.name(metric)).c_str(),
                    experiments::metricValue(m, metric));
    if (!args.diff.empty()) {
        const double scale = args.diffScale > 0 ? args.diffScale : m.max;
        experiments::writeDifferenceImage(args.diff, a, b, scale);
        // Beside the metrics, in their "name value" form: the difference shown white.
        std::printf("diff_scale %.9g\n", scale);
    }
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
