// The report of `lamina reciprocity`: summary.md (the pairs, the BSDFs and the verdict, echoed
// on the console), the mean image of every integrator and the t-statistic maps of every pair.
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/reciprocity.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

#include <algorithm>

namespace lamina::experiments {

namespace {

/// The batches' mean as an image (linear RGB).
render::RgbImage meanImage(const BatchImages& images) {
    render::RgbImage image;
    image.width = images.width();
    image.height = images.height();
    image.pixels.reserve(images.meanImage().size() * 3);
    for (const Rgb<double>& v : images.meanImage())
        for (int c = 0; c < 3; ++c)
            image.pixels.push_back(float(v[c]));
    return image;
}

// The pair's row of the summary's table; its EXR of t statistics and their figures.
std::string writePair(const PairAgreement& p, double alpha, Report& report) {
    const bool pixelTestTrusted = p.pixelTest.trustworthy;
    const AgreementResult& r = p.result;
    const int width = p.width, height = p.height;
    const std::string row = formatText(
        "| %s vs %s | %.2f%% of %d%s | %.2f%% of %d (p %.2g) | %+.4f +- %.4f (p %.2g) | %s |\n",
        p.nameA.c_str(), p.nameB.c_str(), 100 * r.pixelRejectionRate(), r.pixelsTested,
        pixelTestTrusted ? "" : " (not meaningful: see the verdict)", 100 * r.blockRejectionRate(),
        r.blocksTested, r.blockRejectionPValue(alpha), r.relativeDifference, r.standardError,
        r.meanPValue, p.agree ? "agree" : "DISAGREE");
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
        MapFigure map;
        map.title =
            formatText("Welch t per %s, %s vs %s (red: %s brighter)", pixels ? "pixel" : "block",
                       p.nameA.c_str(), p.nameB.c_str(), p.nameA.c_str());
        map.quantity = "Welch t";
        map.unit = "dimensionless";
        map.width = width;
        map.height = height;
        map.values = pixels ? r.pixelT : r.blockT;
        map.isSigned = true;  // diverging, symmetric about 0 (agreement)
        map.caption =
            "Under agreement t is about Student-t distributed with (batches - 1) degrees of "
            "freedom; a region of one colour is where the images differ.";
        report.addFigure(stem + (pixels ? "_pixels" : "_blocks"), map);
    }
    return row;
}

std::string materialRow(const MaterialReciprocity& m) {
    const BsdfReciprocity& r = m.check;
    return formatText("| %s | %s | %.2e | %.2e | %s |\n", m.material.c_str(),
                      std::string(render::kRenderModeNames.name(m.mode)).c_str(),
                      r.maxReciprocityError, r.maxAdjointError,
                      r.maxAdjointError > 1e-3       ? "ADJOINT BROKEN"
                      : r.maxReciprocityError > 1e-3 ? "not reciprocal"
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
    std::string md = formatText(
        "# Reciprocity: do the estimators converge to the same image?\n\n"
        "`%s`, %s mode, %d spp in %d independent batches per integrator, alpha %.3g, %dx%d "
        "blocks. Each pair's images are compared per pixel and per block (Welch t-tests on the "
        "batches) and by their image means (relative difference with its standard error).\n\n",
        in.scene.c_str(), mode.c_str(), in.spp, in.batches, in.test.alpha, in.test.blockSize,
        in.test.blockSize);
    std::string images;
    for (const IntegratorBatches& r : result.renders) {
        const std::string name(render::kIntegratorNames.name(r.integrator));
        render::ImageMetadata meta;
        meta.strings["integrator"] = name;
        meta.strings["mode"] = mode;
        meta.ints["spp"] = in.spp;
        meta.ints["batches"] = in.batches;
        const render::RgbImage mean = meanImage(r.images);
        render::writeFloatExr(report.file(name + ".exr"), mean.width, mean.height, {"R", "G", "B"},
                              mean.pixels, meta);
        images +=
            formatText("%s`%s.exr` (%.1f s)", images.empty() ? "" : ", ", name.c_str(), r.seconds);
    }
    md +=
        "| pair | pixels rejected | blocks rejected | mean rel. diff | verdict |\n"
        "|---|---|---|---|---|\n";
    std::string maps;
    for (const PairAgreement& p : result.pairs) {
        md += writePair(p, in.test.alpha, report);
        const auto meanOf = [&](const std::string& integrator) {
            if (integrator == "reference") return render::readLinearRgbImage(in.reference);
            for (const IntegratorBatches& r : result.renders)
                if (render::kIntegratorNames.name(r.integrator) == integrator)
                    return meanImage(r.images);
            throw std::logic_error("reciprocity: no render of " + integrator);
        };
        report.addImagePair(p.nameA + "_vs_" + p.nameB,
                            imagePair(meanOf(p.nameA), p.nameA, meanOf(p.nameB), p.nameB,
                                      "Mean images: " + p.nameA + " against " + p.nameB));
        maps += formatText("![%s vs %s, blocks](t_%s_vs_%s_blocks.png) ", p.nameA.c_str(),
                           p.nameB.c_str(), p.nameA.c_str(), p.nameB.c_str());
    }
    md += formatText("\nBSDFs (max relative error over %d direction pairs):\n\n",
                     kBsdfReciprocityPairs);
    md += "| material | mode | reciprocity (reflection) | adjoint | |\n|---|---|---|---|---|\n";
    for (const MaterialReciprocity& m : result.materials)
        md += materialRow(m);
    md += formatText("\nverdict: %s%s (images and t statistics in %s)\n\n",
                     result.allAgree ? "the estimators agree" : "the estimators DISAGREE",
                     pixelTestNote(result).c_str(), report.directory().string().c_str());
    const int perBatch = std::max(1, in.spp / in.batches);
    md += formatText(
        "Premises of the verdict: (1) independent renders: every batch is a render of its own "
        "seed (derived from --seed %llu, the integrator and the batch) with the independent "
        "sampler, so the %d batch means of a pixel or a block are independent, their spread "
        "estimates the variance of their mean with %d degrees of freedom, and the integrators "
        "share no random numbers; (2) samples: each batch has %d spp, so a block's batch mean "
        "averages %d samples (%dx%d pixels; fewer at the image's edges), enough for the "
        "block means to be near normal, which Welch's test assumes (the per-pixel test, %d "
        "samples a batch, is checked by the bootstrap above); (3) significance: every "
        "per-pixel and per-block test at alpha %.3g, and the verdict \"disagree\" only when "
        "the number of rejected blocks (binomial at alpha) or the difference of the image "
        "means (Welch) is significant at 0.001. The noise floor of the image means' relative "
        "difference is its standard error (the +- column): a difference whose p-value is "
        "above 0.001 is not resolved at %d spp.\n\n",
        static_cast<unsigned long long>(in.seed), in.batches, in.batches - 1, perBatch,
        perBatch * in.test.blockSize * in.test.blockSize, in.test.blockSize, in.test.blockSize,
        perBatch, in.test.alpha, in.spp);
    md += "Mean images: " + images +
          "; per pair, its t statistics per pixel and per block (`t_A_vs_B.exr`, "
          "`t_A_vs_B_pixels.png`, `t_A_vs_B_blocks.png`, each also as PDF):\n\n" +
          maps + "\n";
    report.addSummary(md);
}

}  // namespace lamina::experiments
