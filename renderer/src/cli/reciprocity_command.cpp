// `lamina reciprocity SCENE -o DIR`: do camera tracing, light tracing and BDPT converge to
// the same image? Each integrator renders the scene as independent batches with its own
// seeds (estimator_agreement.h); every pair (and each against a reference image, if given)
// is tested per pixel and per 8x8 block; the BSDF of every material is checked for
// reciprocity and for the adjoint identity in both modes. Exit status 2 if a pair disagrees.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <sstream>

#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/reciprocity_check.h"
#include "lamina/cli/option_parsing.h"
#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/render/estimator_agreement.h"
#include "lamina/render/image_output.h"

namespace lamina::cli {

namespace {

struct ReciprocityArgs {
    std::string scene;
    std::string output;
    std::string integrators = "path,light,bdpt";
    std::string mode = "rgb";
    std::string reference;
    std::string ablate;
    std::string resolution;
    int spp = 256;
    int batches = 16;
    int maxDepth = 0;
    long long seed = 0;
    double alpha = 0.01;
    int block = 8;
    int threads = 0;
};

struct Rendered {
    std::string name;
    render::BatchImages images;
    double seconds;
};

render::BatchImages referenceImages(const std::string& path, int width, int height) {
    const render::RgbImage img = render::readRgbImage(path);
    if (img.width != width || img.height != height)
        throw InputError(path + " is " + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + " but the renders are " +
                         std::to_string(width) + "x" + std::to_string(height));
    render::Film film(width, height, render::FilmSpace::Rec709);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            film.addSample(x, y, Rgb<double>(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)),
                           1.0);
    render::BatchImages images(width, height);
    images.add(film);
    return images;
}

void writeMean(const std::filesystem::path& path, const render::BatchImages& images,
               const render::ImageMetadata& meta) {
    std::vector<float> data;
    data.reserve(images.meanImage().size() * 3);
    for (const Rgb<double>& v : images.meanImage())
        for (int c = 0; c < 3; ++c)
            data.push_back(float(v[c]));
    render::writeFloatExr(path, images.width(), images.height(), {"R", "G", "B"}, data, meta);
}

bool comparePair(const std::filesystem::path& dir, const std::string& nameA,
                 const render::BatchImages& a, const std::string& nameB,
                 const render::BatchImages& b, const ReciprocityArgs& args) {
    render::AgreementTest test;
    test.alpha = args.alpha;
    test.blockSize = args.block;
    const render::AgreementResult r = render::testAgreement(a, b, test);
    const bool agree = r.agree(args.alpha);
    std::printf(
        "%-6s vs %-9s  pixels rejected %6.2f%% of %d  blocks rejected %6.2f%% of %d "
        "(p %.2g)  mean rel. diff %+.4f +- %.4f (p %.2g)  %s\n",
        nameA.c_str(), nameB.c_str(), 100 * r.pixelRejectionRate(), r.pixelsTested,
        100 * r.blockRejectionRate(), r.blocksTested, r.blockRejectionPValue(args.alpha),
        r.relativeDifference, r.standardError, r.meanPValue, agree ? "agree" : "DISAGREE");
    const std::string stem = "t_" + nameA + "_vs_" + nameB;
    std::vector<float> data;
    data.reserve(r.pixelT.size() * 2);
    for (std::size_t i = 0; i < r.pixelT.size(); ++i) {
        data.push_back(r.pixelT[i]);
        data.push_back(r.blockT[i]);
    }
    render::ImageMetadata meta;
    meta.floats["alpha"] = float(args.alpha);
    meta.floats["pixel_rejection_rate"] = float(r.pixelRejectionRate());
    meta.floats["block_rejection_rate"] = float(r.blockRejectionRate());
    meta.floats["relative_difference"] = float(r.relativeDifference);
    meta.floats["relative_difference_se"] = float(r.standardError);
    render::writeFloatExr(dir / (stem + ".exr"), a.width(), a.height(), {"T.pixel", "T.block"},
                          data, meta);
    render::writeSignedHeatMap(dir / (stem + "_pixels.png"), a.width(), a.height(), r.pixelT, 4.0);
    render::writeSignedHeatMap(dir / (stem + "_blocks.png"), a.width(), a.height(), r.blockT, 4.0);
    return agree;
}

template <SpectrumType S>
void checkMaterials(const render::SceneDesc& scene, const SpectrumContext<S>& context,
                    const char* modeName) {
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const auto bsdf = buildBxdf(scene.materials[m], context);
        const ReciprocityReport r = checkBsdfReciprocity(*bsdf, 20000, 1 + m);
        std::printf("  %-20s %-8s  reciprocity (reflection) %9.2e   adjoint %9.2e%s\n",
                    scene.materialNames[m].c_str(), modeName, r.maxReciprocityError,
                    r.maxAdjointError,
                    r.maxAdjointError > 1e-3       ? "  ADJOINT BROKEN"
                    : r.maxReciprocityError > 1e-3 ? "  (not reciprocal)"
                                                   : "");
    }
}

int run(const ReciprocityArgs& args) {
    const render::SceneDesc scene = render::loadScene(args.scene);
    const std::filesystem::path dir = args.output;
    std::filesystem::create_directories(dir);

    render::RenderOptions o;
    o.mode =
        args.mode == "spectral" ? render::RenderModeKind::Spectral : render::RenderModeKind::Rgb;
    o.threads = args.threads;
    if (args.maxDepth > 0) o.maxDepth = args.maxDepth;
    if (!args.resolution.empty()) o.resolution = parseResolution(args.resolution);
    for (const std::string& a : splitList(args.ablate)) {
        if (a == "adjoint-correction")
            o.ablations.noAdjointCorrection = true;
        else if (a == "transport-mode")
            o.ablations.radianceOnLightPaths = true;
        else if (a == "swapped-directions")
            o.ablations.swappedConnections = true;
        else
            throw CLI::ValidationError("--ablate", "unknown \"" + a +
                                                       "\"; expected adjoint-correction, "
                                                       "transport-mode, swapped-directions");
    }

    std::printf(
        "reciprocity: %s, %s mode, %d spp in %d independent batches per integrator, "
        "alpha %.3g, %dx%d blocks\n",
        args.scene.c_str(), args.mode.c_str(), args.spp, args.batches, args.alpha, args.block,
        args.block);
    std::vector<Rendered> renders;
    const auto names = splitList(args.integrators);
    for (std::size_t i = 0; i < names.size(); ++i) {
        o.integrator = integratorByName(names[i], "--integrators");
        o.seed = hashValues({std::uint64_t(args.seed), i, 0x7265636970ull}) & 0x7fffffffull;
        const auto start = std::chrono::steady_clock::now();
        render::BatchImages images =
            render::renderBatches(scene, o, args.spp, args.batches, [&](int k) {
                std::fprintf(stderr, "\r%s: batch %d/%d", names[i].c_str(), k + 1, args.batches);
            });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, " (%.1f s)\n", seconds);
        render::ImageMetadata meta;
        meta.strings["integrator"] = names[i];
        meta.strings["mode"] = args.mode;
        meta.ints["spp"] = args.spp;
        meta.ints["batches"] = args.batches;
        writeMean(dir / (names[i] + ".exr"), images, meta);
        renders.push_back({names[i], std::move(images), seconds});
    }

    bool allAgree = true;
    for (std::size_t i = 0; i < renders.size(); ++i)
        for (std::size_t j = i + 1; j < renders.size(); ++j)
            allAgree &= comparePair(dir, renders[i].name, renders[i].images, renders[j].name,
                                    renders[j].images, args);
    if (!args.reference.empty()) {
        const render::BatchImages ref = referenceImages(
            args.reference, renders.front().images.width(), renders.front().images.height());
        for (const Rendered& r : renders)
            allAgree &= comparePair(dir, r.name, r.images, "reference", ref, args);
    }

    std::printf("BSDFs (max relative error over 20000 direction pairs):\n");
    checkMaterials(scene, SpectrumContext<Rgb<double>>{}, "rgb");
    SampledWavelengths<double> lambda =
        SampledWavelengths<double>::fixed({450.0, 520.0, 590.0, 660.0});
    checkMaterials(scene, SpectrumContext<SampledSpectrum<double>>{lambda}, "spectral");

    std::printf("verdict: %s (images and t statistics in %s)\n",
                allAgree ? "the estimators agree" : "the estimators DISAGREE",
                dir.string().c_str());
    return allAgree ? 0 : 2;
}

}  // namespace

void registerReciprocityCommand(CLI::App& app) {
    auto a = std::make_shared<ReciprocityArgs>();
    CLI::App* cmd = app.add_subcommand(
        "reciprocity",
        "Test whether path, light and bdpt converge to the same image (per-pixel and blockwise "
        "t-tests) and whether every BSDF is reciprocal; exit status 2 if they disagree");
    cmd->add_option("scene", a->scene, "Scene file")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", a->output, "Directory for the images and t-statistic maps")
        ->required();
    cmd->add_option("--integrators", a->integrators, "Comma-separated list")->capture_default_str();
    cmd->add_option("--spp", a->spp, "Samples per pixel per integrator (over all batches)")
        ->check(CLI::Range(2, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--batches", a->batches,
                    "Independent batches per integrator (the variance estimate's sample size)")
        ->check(CLI::Range(2, 4096))
        ->capture_default_str();
    cmd->add_option("--mode", a->mode, "Render mode")
        ->check(CLI::IsMember({"rgb", "spectral"}))
        ->capture_default_str();
    cmd->add_option("--reference", a->reference, "Also test each integrator against this EXR")
        ->check(CLI::ExistingFile);
    cmd->add_option("--alpha", a->alpha, "Significance level of each test")
        ->check(CLI::Range(1e-6, 0.5))
        ->capture_default_str();
    cmd->add_option("--block", a->block, "Block size of the blockwise test")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    cmd->add_option("--resolution", a->resolution, "Image size WIDTHxHEIGHT (overrides)");
    cmd->add_option("--max-depth", a->maxDepth, "Maximum scattering events per path")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--seed", a->seed, "Base seed")->check(CLI::Range(0LL, 2147483647LL));
    cmd->add_option("--threads", a->threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--ablate", a->ablate,
                    "Reproduce a known bug on purpose: adjoint-correction (drop the shading-normal "
                    "factor on light paths), transport-mode (radiance's 1/eta^2 on light paths), "
                    "swapped-directions (f(wi, wo) at light-path connections)");
    cmd->callback([a] {
        const int status = run(*a);
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

}  // namespace lamina::cli
