// The report of `lamina media SCENE...`: per scene the renders (EXR, PNG), the image pairs for
// the report page, the relative difference and CIEDE2000 figures of RGB against spectral mode,
// the error figures of the spectral render with and without spectral MIS against the
// reference, and summary.md with the premises of every reference.
#include <algorithm>
#include <cmath>

#include "lamina/experiments/media.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

/// A per-pixel map of a distance (sequential from 0).
MapFigure pixelMap(const MediaSceneResult& r, std::vector<float> values, std::string title,
                   std::string quantity) {
    MapFigure map = pixelMapFigure(std::move(values), r.width, r.height,
                                   title + " (" + r.scene + ")", std::move(quantity));
    map.fromZero = true;
    return map;
}

void writeRenders(const MediaSceneResult& r, Report& report) {
    render::ImageMetadata meta;
    meta.ints["spp"] = r.spp;
    for (const auto& [suffix, film] :
         {std::pair<std::string, const render::Film*>{"spectral", r.spectralMis.render.film.get()},
          {"rgb", r.rgb.film.get()},
          {"hero_only", r.heroOnly.render.film.get()}}) {
        render::writeExr(report.file(r.name + "_" + suffix + ".exr"), *film, false, meta);
        render::writePngPreview(report.file(r.name + "_" + suffix + ".png"), *film, 0.0);
    }
    const render::RgbImage spectral = filmImage(*r.spectralMis.render.film);
    report.addImagePair(r.name + "_rgb_spectral",
                        imagePair(spectral, "spectral mode", filmImage(*r.rgb.film), "RGB mode",
                                  "The scene in spectral and in RGB mode (" + r.scene + ")"));
    report.addImagePair(
        r.name + "_spectral_mis",
        imagePair(
            filmImage(*r.heroOnly.render.film), "without spectral MIS", spectral, "spectral MIS",
            "Spectral mode without and with spectral MIS over the wavelengths (" + r.scene + ")"));
    report.addImagePair(
        r.name + "_reference",
        imagePair(spectral, "spectral MIS", r.reference, "reference",
                  "Spectral mode with spectral MIS against the reference (" + r.scene + ")"));
}

void writeFigures(const MediaSceneResult& r, Report& report) {
    MapFigure relative =
        pixelMap(r, r.relative.values, "Relative difference of the luminance, RGB against spectral",
                 "|Y RGB - Y spectral| / mean Y");
    relative.upper = 2.0;  // the quantity's whole range: the same colours in every report
    relative.caption =
        "Symmetric relative difference, 0 to 2; grey: black in both renders. Both renders' noise "
        "included.";
    report.addFigure(r.name + "_relative_difference", relative);

    MapFigure de = pixelMap(r, r.ciede2000.values, "CIEDE2000 of each pixel, RGB against spectral",
                            "CIEDE2000");
    de.caption = "Both renders' noise included.";
    report.addFigure(r.name + "_ciede2000", de);

    // The two estimators' errors on one scale, so that the maps compare: the larger of the two
    // 99th percentiles.
    MapFigure mis =
        differenceFigure(filmImage(*r.spectralMis.render.film), r.reference,
                         "Error of spectral MIS against the reference (" + r.scene + ")");
    MapFigure hero =
        differenceFigure(filmImage(*r.heroOnly.render.film), r.reference,
                         "Error without spectral MIS against the reference (" + r.scene + ")");
    const double upper = std::max(percentileOf(mis.values, 99), percentileOf(hero.values, 99));
    if (upper > 0) {
        mis.upper = upper;
        hero.upper = upper;
        mis.clipReason = hero.clipReason =
            "one scale for both estimators: the larger of their 99th percentiles";
    }
    const std::string caption = formatText(
        "%d spp; the reference's own noise included. The same colour scale as the other "
        "estimator's map.",
        r.spp);
    mis.caption = caption;
    hero.caption = caption;
    report.addFigure(r.name + "_error_spectral_mis", mis);
    report.addFigure(r.name + "_error_hero_only", hero);
}

std::string cell(const FlooredStatistic& s, int spp) {
    return describeReading(readAgainstFloor(s.value, s.floor, spp), spp);
}

FlooredStatistic percent(const FlooredStatistic& s) {
    return {100 * s.value, 100 * s.floor, 100 * s.otherSeed};
}

std::string sceneSummary(const MediaSceneResult& r) {
    const render::RenderSettings& s = r.spectralMis.render.settings;
    std::string md = formatText(
        "## %s\n\n"
        "%dx%d, %d spp, %s integrator, max depth %d. ![spectral mode](%s_spectral.png) "
        "![RGB mode](%s_rgb.png) ![spectral mode without spectral MIS](%s_hero_only.png)\n\n"
        "### RGB against spectral mode\n\n"
        "The RGB render against the spectral one (the reference of this comparison), both with "
        "the same seed: relMSE %.4g, MAE %.4g.\n\n"
        "| RGB against spectral | value (noise floor) | with the second seed | two independent "
        "spectral renders |\n"
        "|---|---|---|---|\n",
        r.scene.c_str(), r.width, r.height, r.spp,
        std::string(render::kIntegratorNames.name(s.integrator)).c_str(), s.maxDepth,
        r.name.c_str(), r.name.c_str(), r.name.c_str(), r.rgbMetrics.relmse, r.rgbMetrics.mae);
    const auto row = [&](const char* what, const FlooredStatistic& f, double independent) {
        md += formatText("| %s | %s | %.2f | %.2f |\n", what, cell(f, r.spp).c_str(), f.otherSeed,
                         independent);
    };
    row("mean relative difference of the luminance (%)", percent(r.relative.mean),
        100 * r.independent.meanRelative);
    row("95th percentile of the relative difference (%)", percent(r.relative.p95),
        100 * r.independent.p95Relative);
    row("mean CIEDE2000", r.ciede2000.mean, r.independent.meanDeltaE);
    row("95th percentile of CIEDE2000", r.ciede2000.p95, r.independent.p95DeltaE);
    md += formatText(
        "\nOver the %zu pixels not black in both renders. ![relative difference](%s_relative_"
        "difference.png) ![CIEDE2000](%s_ciede2000.png)\n\n",
        r.comparedPixels, r.name.c_str(), r.name.c_str());

    const double ratio =
        r.heroOnly.efficiency > 0 ? r.spectralMis.efficiency / r.heroOnly.efficiency : NAN;
    const double variance = r.spectralMis.metrics.relmse > 0
                                ? r.heroOnly.metrics.relmse / r.spectralMis.metrics.relmse
                                : NAN;
    md += formatText(
        "### Spectral MIS against the hero wavelength alone\n\n"
        "Both in spectral mode with the same seed and %d spp, scored against the reference "
        "(%s%s).\n\n"
        "| spectral mode | relMSE (standard error) | seconds | efficiency 1 / (relMSE x s) |\n"
        "|---|---|---|---|\n"
        "| spectral MIS over the wavelengths | %.4g (%.2g) | %.2f | %.4g |\n"
        "| the hero's free-flight density alone (`--ablate media-spectral-mis`) | %.4g (%.2g) | "
        "%.2f | %.4g |\n\n"
        "Spectral MIS is %s as efficient (relMSE %s at equal samples). "
        "![error with spectral MIS](%s_error_spectral_mis.png) "
        "![error without](%s_error_hero_only.png)\n\n",
        r.spp, r.referenceName.c_str(),
        r.referenceSeconds > 0 ? formatText(", %.1f s", r.referenceSeconds).c_str() : "",
        r.spectralMis.metrics.relmse, r.spectralMis.metrics.relmseStandardError,
        r.spectralMis.render.seconds, r.spectralMis.efficiency, r.heroOnly.metrics.relmse,
        r.heroOnly.metrics.relmseStandardError, r.heroOnly.render.seconds, r.heroOnly.efficiency,
        std::isfinite(ratio) ? formatText("%.3g times", ratio).c_str() : "(not measured)",
        std::isfinite(variance) ? formatText("%.3g times smaller", variance).c_str()
                                : "not measured",
        r.name.c_str(), r.name.c_str());
    md += "Premises of the reference:\n\n";
    for (const Premise& p : r.premises)
        md += "- " + describePremise(p) + "\n";
    return md + "\n";
}

}  // namespace

void writeMediaReport(const MediaResult& result, Report& report) {
    std::string md =
        "# Participating media: RGB against spectral mode, and spectral MIS\n\n"
        "Each scene rendered in spectral mode (the reference of the comparison), in RGB mode with "
        "the same seed and samples, and in spectral mode without the spectral MIS over the "
        "wavelengths (each wavelength weighted by the hero's free-flight density alone, "
        "`--ablate media-spectral-mis`, docs/media.md).\n\n";
    md += formatText(
        "**RGB against spectral.** A chromatic medium's transmittance exp(-sigma_t(lambda) d) "
        "varies within each RGB channel's band, and RGB mode's exp(-sigma_t d) per channel is "
        "not the band's average. The relative difference of a pixel is |Y_RGB - Y_spectral| / "
        "((Y_RGB + Y_spectral) / 2), in [0, 2]. Premises of the noise floor: the two modes share "
        "their seed (common random numbers), so their difference is far less noisy than that of "
        "two independent renders; its noise is measured from a second pair with another seed: "
        "per pixel and channel n = ((RGB1 - spectral1) - (RGB2 - spectral2)) / sqrt(2) has the "
        "variance of the first pair's difference and no true difference in it, and the floor is "
        "the same statistic between m + n/2 and m - n/2, m the mean of the first pair "
        "(noise_floor.h). A difference is resolved when it exceeds %g times its floor; otherwise "
        "it is not resolved at this sample count, and the samples that would resolve it are "
        "estimated with the noise falling as 1/sqrt(spp). Beside it, the difference between the "
        "second pair (a real difference shows in both) and the same statistic between the two "
        "independent spectral renders: the floor two independent renders would have (every "
        "sampler number changes with the seed; sobol-global, whose film positions do not, is "
        "refused).\n\n",
        kResolvedOverFloor);
    md +=
        "**Spectral MIS.** Efficiency is 1 / (relMSE x render seconds), relMSE = mean((x - "
        "ref)^2 / (ref^2 + 1e-2)) against a converged spectral reference. Premises, checked as "
        "`lamina convergence` checks them: the reference is of the same mode, resolution, scene "
        "files, max depth and integrator settings, independent of the measured renders (another "
        "seed), and its own noise, mean(Var(ref) / (ref^2 + 1e-2)), is at most 10% of the "
        "smaller measured relMSE (it adds to every relMSE). A reference the experiment renders "
        "itself has these by construction but its own noise, which is measured; a given one "
        "that fails a premise is refused. The seconds are wall time on a machine that may be "
        "shared: the relMSE at equal samples is the load-independent part of the comparison.\n\n";
    for (const MediaSceneResult& r : result.scenes) {
        writeRenders(r, report);
        writeFigures(r, report);
        md += sceneSummary(r);
    }
    md +=
        "Files: per scene NAME_spectral.exr, NAME_rgb.exr, NAME_hero_only.exr (spectral mode "
        "without spectral MIS), their PNG previews, and the figures' data.\n";
    report.addSummary(md);
}

}  // namespace lamina::experiments
