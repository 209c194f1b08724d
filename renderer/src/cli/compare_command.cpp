// `lamina compare A.exr B.exr`: error metrics of A against the reference B (image_metrics.h)
// and, optionally, a false-colour picture of |A - B|.
#include <OpenImageIO/imageio.h>

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

void writeDiff(const std::string& path, const render::RgbImage& a, const render::RgbImage& b,
               double scale) {
    std::vector<float> img(std::size_t(a.width) * a.height * 3);
    for (std::size_t p = 0; p < std::size_t(a.width) * a.height; ++p) {
        double d = 0;
        for (int c = 0; c < 3; ++c)
            d += std::abs(double(a.pixels[p * 3 + c]) - double(b.pixels[p * 3 + c])) / 3;
        // Black - blue - red - yellow by |A - B| relative to the largest difference.
        const double t = scale > 0 ? std::clamp(d / scale, 0.0, 1.0) : 0.0;
        img[p * 3 + 0] = float(std::clamp(2 * t - 0.5, 0.0, 1.0));
        img[p * 3 + 1] = float(std::clamp(2 * t - 1.0, 0.0, 1.0));
        img[p * 3 + 2] = float(t < 0.5 ? 2 * t : 2 - 2 * t);
    }
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw InputError(path + ": cannot write this image format (use .png)");
    OIIO::ImageSpec spec(a.width, a.height, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, img.data()) ||
        !out->close())
        throw InputError(path + ": cannot write: " + out->geterror());
}

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
    if (!args.diff.empty()) writeDiff(args.diff, a, b, m.max);
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
