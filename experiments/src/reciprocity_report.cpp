// The report of `lamina reciprocity`: the log on the console, the mean image of every
// integrator and the t-statistic maps of every pair.
#include "lamina/experiments/reciprocity.h"
#include "lamina/experiments/svg_heat_map.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

void writeMean(const std::filesystem::path& path, const BatchImages& images,
               const render::ImageMetadata& meta) {
    std::vector<float> data;
    data.reserve(images.meanImage().size() * 3);
    for (const Rgb<double>& v : images.meanImage())
        for (int c = 0; c < 3; ++c)
            data.push_back(float(v[c]));
    render::writeFloatExr(path, images.width(), images.height(), {"R", "G", "B"}, data, meta);
}

void writePair(const PairAgreement& p, double alpha, const Report& report) {
    const bool pixelTestTrusted = p.pixelTest.trustworthy;
    const AgreementResult& r = p.result;
    const int width = p.width, height = p.height;
    report.print(formatText(
        "%-6s vs %-9s  pixels rejected %6.2f%% of %d%s  blocks rejected %6.2f%% of %d "
        "(p %.2g)  mean rel. diff %+.4f +- %.4f (p %.2g)  %s\n",
        p.nameA.c_str(), p.nameB.c_str(), 100 * r.pixelRejectionRate(), r.pixelsTested,
        pixelTestTrusted ? "" : " (not meaningful: see the verdict)", 100 * r.blockRejectionRate(),
        r.blocksTested, r.blockRejectionPValue(alpha), r.relativeDifference, r.standardError,
        r.meanPValue, p.agree ? "agree" : "DISAGREE"));
    const std::string stem = "t_" + p.nameA + "_vs_" + p.nameB;
    std::vector<float> data;
    data.reserve(r.pixelT.size() * 2);
    for (std::size_t i = 0; i < r.pixelT.size(); ++i) {
        data.push_back(r.pixelT[i]);
        data.push_back(r.blockT[i]);
    }
    render::ImageMetadata meta;
    meta.floats["alpha"] = float(alpha);
    meta.floats["pixel_rejection_rate"] = float(r.pixelRejectionRate());
    meta.floats["block_rejection_rate"] = float(r.blockRejectionRate());
    meta.floats["relative_difference"] = float(r.relativeDifference);
    meta.floats["relative_difference_se"] = float(r.standardError);
    render::writeFloatExr(report.file(stem + ".exr"), width, height, {"T.pixel", "T.block"}, data,
                          meta);
    for (const bool pixels : {true, false}) {
        SvgHeatMap map(
            formatText("Welch t per %s, %s vs %s (red: %s brighter)", pixels ? "pixel" : "block",
                       p.nameA.c_str(), p.nameB.c_str(), p.nameA.c_str()),
            width, height, pixels ? r.pixelT : r.blockT);
        map.setScale(Palette::Diverging, -4, 4, "t (saturated at |t| = 4)");
        const std::string name = stem + (pixels ? "_pixels" : "_blocks");
        map.write(report.file(name + ".svg"), report.file(name + ".png"));
    }
}

std::string materialLine(const MaterialReciprocity& m) {
    const BsdfReciprocity& r = m.check;
    return formatText("  %-20s %-8s  reciprocity (reflection) %9.2e   adjoint %9.2e%s\n",
                      m.material.c_str(),
                      std::string(render::kRenderModeNames.name(m.mode)).c_str(),
                      r.maxReciprocityError, r.maxAdjointError,
                      r.maxAdjointError > 1e-3       ? "  ADJOINT BROKEN"
                      : r.maxReciprocityError > 1e-3 ? "  (not reciprocal)"
                                                     : "");
}

/// The verdict rests on the blocks and the image means; when the per-pixel test does not hold
/// its level at this sample count (calibratePixelTest), its rejection rates above are noise
/// of the test, not evidence, and the verdict says so.
std::string pixelTestNote(const ReciprocityResult& result) {
    const ReciprocityInputs& in = result.inputs;
    const PixelTestCalibration& c = result.pixelTest;
    if (!c.checked)
        return " by the blocks and the image means; with fewer than 4 batches the per-pixel "
               "test's own level cannot be checked";
    if (c.trustworthy) return "";
    return formatText(
        " by the blocks and the image means; the per-pixel rejection rates are not "
        "meaningful at %d spp in %d batches: with these heavy-tailed samples the per-pixel "
        "test would reject %.1f%% of pixels at alpha %.3g even if the estimators agreed "
        "(bootstrap); it needs at least about %d spp in %d batches to hold its level",
        in.spp, in.batches, 100 * c.nullRejectionRate, in.test.alpha, c.recommendedSpp, in.batches);
}

}  // namespace

void writeReciprocityReport(const ReciprocityResult& result, Report& report) {
    const ReciprocityInputs& in = result.inputs;
    const std::string mode(render::kRenderModeNames.name(in.mode));
    report.print(
        formatText("reciprocity: %s, %s mode, %d spp in %d independent batches per integrator, "
                   "alpha %.3g, %dx%d blocks\n",
                   in.scene.c_str(), mode.c_str(), in.spp, in.batches, in.test.alpha,
                   in.test.blockSize, in.test.blockSize));
    for (const IntegratorBatches& r : result.renders) {
        const std::string name(render::kIntegratorNames.name(r.integrator));
        render::ImageMetadata meta;
        meta.strings["integrator"] = name;
        meta.strings["mode"] = mode;
        meta.ints["spp"] = in.spp;
        meta.ints["batches"] = in.batches;
        writeMean(report.file(name + ".exr"), r.images, meta);
    }
    for (const PairAgreement& p : result.pairs)
        writePair(p, in.test.alpha, report);

    report.print(
        formatText("BSDFs (max relative error over %d direction pairs):\n", kBsdfReciprocityPairs));
    for (const MaterialReciprocity& m : result.materials)
        report.print(materialLine(m));
    report.print(formatText("verdict: %s%s (images and t statistics in %s)\n",
                            result.allAgree ? "the estimators agree" : "the estimators DISAGREE",
                            pixelTestNote(result).c_str(), report.directory().string().c_str()));
}

}  // namespace lamina::experiments
