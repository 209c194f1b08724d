// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour picture of |A - B|.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/experiments/image_metrics.h"
#include "option_parsing.h"

namespace lamina::app {

namespace {

struct CompareArgs {
    std::string a, b;
    std::string metrics = experiments::kMetricNames.list(",");
    std::string diff;
};

void run(const CompareArgs& args) {
    const render::RgbImage a = render::readRgbImage(args.a);
    const render::RgbImage b = render::readRgbImage(args.b);
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
    if (!args.diff.empty()) experiments::writeDifferenceImage(args.diff, a, b, m.max);
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
    cmd->add_option("--diff", a->diff, "Write a false-colour PNG of |image - reference|");
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::app
