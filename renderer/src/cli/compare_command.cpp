// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour picture of |A - B|.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/render/image_metrics.h"

namespace lamina::cli {

namespace {

struct CompareArgs {
    std::string a, b;
    std::string metrics = "mse,rmse,relmse,mae,max";
    std::string diff;
};

void run(const CompareArgs& args) {
    const render::RgbImage a = render::readRgbImage(args.a);
    const render::RgbImage b = render::readRgbImage(args.b);
    if (a.width != b.width || a.height != b.height)
        throw InputError(args.a + " is " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " but " + args.b + " is " +
                         std::to_string(b.width) + "x" + std::to_string(b.height));
    const render::ImageMetrics m = render::compareImages(a, b);
    std::stringstream list(args.metrics);
    for (std::string name; std::getline(list, name, ',');) {
        double v;
        if (name == "mse")
            v = m.mse;
        else if (name == "rmse")
            v = m.rmse;
        else if (name == "relmse")
            v = m.relmse;
        else if (name == "mae")
            v = m.mae;
        else if (name == "max")
            v = m.max;
        else
            throw CLI::ValidationError("--metric", "unknown metric \"" + name +
                                                       "\"; expected mse, rmse, relmse, mae, max");
        std::printf("%s %.9g\n", name.c_str(), v);
    }
    if (!args.diff.empty()) render::writeDifferenceImage(args.diff, a, b, m.max);
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
    cmd->add_option("--metric", a->metrics, "Comma-separated: mse, rmse, relmse, mae, max")
        ->capture_default_str();
    cmd->add_option("--diff", a->diff, "Write a false-colour PNG of |image - reference|");
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::cli
