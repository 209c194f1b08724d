// The report of `lamina polarisation SCENE`: the three renders (EXR; the polarised one with its
// Stokes layers), the images as pairs for the report page, the relative difference and
// CIEDE2000 figures of the spectral and the RGB render against the polarised one, the DoLP and
// AoLP figures, and summary.md.
#include <cmath>

#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/polarisation.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

MapFigure pixelMap(const PolarisationResult& r, std::vector<float> values, std::string title,
                   std::string quantity) {
    return pixelMapFigure(std::move(values), r.width, r.height, title + " (" + r.scene + ")",
                          std::move(quantity));
}

/// The relative difference and CIEDE2000 maps of one mode against the polarised render, named
/// PREFIXrelative_difference and PREFIXciede2000.
void writeDifferenceFigures(const PolarisationResult& r, const AgainstPolarised& a,
                            const std::string& mode, const std::string& prefix, Report& report) {
    MapFigure relative = pixelMap(
        r, a.relative, "Relative difference of the luminance, " + mode + " against polarised",
        "|Y " + mode + " - Y polarised| / mean Y");
    relative.fromZero = true;
    relative.upper = 2.0;  // the quantity's whole range: the same colours in every report
    relative.caption =
        "Symmetric relative difference, 0 to 2; grey: black in both renders. Both "
        "renders' noise included.";
    report.addFigure(prefix + "relative_difference", relative);

    MapFigure de = pixelMap(r, a.ciede2000,
                            "CIEDE2000 of each pixel, " + mode + " against polarised", "CIEDE2000");
    de.fromZero = true;  // a distance: never negative, 0 is agreement
    de.caption = "Both renders' noise included.";
    report.addFigure(prefix + "ciede2000", de);
}

void writePolarisationFigures(const PolarisationResult& r, Report& report) {
    std::vector<float> dolp = r.dolp, aolp = r.aolp;
    for (std::size_t i = 0; i < dolp.size(); ++i) {
        if (!r.lit[i]) dolp[i] = std::nanf("");
        if (!r.lit[i] || r.dolp[i] < r.dolpThreshold) aolp[i] = std::nanf("");
    }
    MapFigure d = pixelMap(r, std::move(dolp), "Degree of linear polarisation", "DoLP");
    d.fromZero = true;
    d.upper = 1.0;  // the quantity's whole range: unpolarised to fully polarised
    d.caption = "sqrt(S1^2 + S2^2) / S0 of the luminance of each Stokes layer; grey: no light.";
    report.addFigure("dolp", d);

    MapFigure a = pixelMap(r, std::move(aolp), "Angle of linear polarisation", "AoLP");
    a.unit = "degrees";
    a.cycle = std::pair{-90.0, 90.0};
    a.caption = formatText(
        "atan2(S2, S1) / 2 in the image frame, counter-clockwise from the image's right; grey: "
        "no light or DoLP below "
        "%g, whose angle is mostly noise.",
        r.dolpThreshold);
    report.addFigure("aolp", a);
}

std::string cell(const FlooredStatistic& s, int spp) {
    return formatText("%s | %.2f",
                      describeReading(readAgainstFloor(s.value, s.floor, spp), spp).c_str(),
                      s.otherSeed);
}

FlooredStatistic percent(const FlooredStatistic& s) {
    return {100 * s.value, 100 * s.floor, 100 * s.otherSeed};
}

/// The summary's table row of one statistic, `of` choosing it from a comparison.
template <typename Of>
std::string row(const char* what, const PolarisationResult& r, Of of, int spp) {
    return formatText("| %s | %s | %s |\n", what, cell(of(r.spectral), spp).c_str(),
                      cell(of(r.rgb), spp).c_str());
}

}  // namespace

void writePolarisationReport(const PolarisationResult& r, Report& report) {
    render::ImageMetadata meta;
    meta.ints["spp"] = r.polarised.spp;
    render::writeExr(report.file("polarised.exr"), *r.polarised.film, false, meta);
    render::writeExr(report.file("spectral.exr"), *r.spectral.render.film, false, meta);
    render::writeExr(report.file("rgb.exr"), *r.rgb.render.film, false, meta);
    render::writePngPreview(report.file("polarised.png"), *r.polarised.film, 0.0);
    render::writePngPreview(report.file("spectral.png"), *r.spectral.render.film, 0.0);
    render::writePngPreview(report.file("rgb.png"), *r.rgb.render.film, 0.0);
    const render::RgbImage p = filmImage(*r.polarised.film);
    const render::RgbImage s = filmImage(*r.spectral.render.film);
    const render::RgbImage c = filmImage(*r.rgb.render.film);
    report.addImagePair("renders", imagePair(p, "polarised mode", s, "spectral mode",
                                             "The scene in the polarised and in the spectral "
                                             "mode (" +
                                                 r.scene + ")"));
    report.addImagePair(
        "rgb_renders",
        imagePair(p, "polarised mode", c, "RGB mode",
                  "The scene in the polarised and in the RGB mode (" + r.scene + ")"));
    writeDifferenceFigures(r, r.spectral, "spectral", "", report);
    writeDifferenceFigures(r, r.rgb, "RGB", "rgb_", report);
    writePolarisationFigures(r, report);

    const int spp = r.polarised.spp;
    std::string md = formatText(
        "# Polarisation: what ignoring it costs in %s\n\n"
        "The scene rendered in the polarised mode (a Stokes vector per wavelength, a Mueller "
        "matrix at every event), in the spectral mode (s and p averaged at every event) and in "
        "the RGB mode, with the same seed, %d spp each (%s integrator), %dx%d. Each is compared "
        "with the polarised render, the reference: the spectral render differs from it by "
        "polarisation alone (relMSE %.4g, MAE %.4g), the RGB render also by RGB mode's colour "
        "and Fresnel approximations (relMSE %.4g, MAE %.4g).\n\n"
        "![polarised mode](polarised.png) ![spectral mode](spectral.png) "
        "![RGB mode](rgb.png)\n\n"
        "| against the polarised render | spectral: value (noise floor) | with the second seed "
        "| RGB: value (noise floor) | with the second seed |\n"
        "|---|---|---|---|---|\n",
        r.scene.c_str(), spp,
        std::string(render::kIntegratorNames.name(r.polarised.settings.integrator)).c_str(),
        r.width, r.height, r.spectral.metrics.relmse, r.spectral.metrics.mae, r.rgb.metrics.relmse,
        r.rgb.metrics.mae);
    md += row(
        "mean relative difference of the luminance (%)", r,
        [](const AgainstPolarised& a) { return percent(a.meanRelative); }, spp);
    md += row(
        "95th percentile of the relative difference (%)", r,
        [](const AgainstPolarised& a) { return percent(a.p95Relative); }, spp);
    md += row(
        "mean CIEDE2000", r, [](const AgainstPolarised& a) { return a.meanDeltaE; }, spp);
    md += row(
        "95th percentile of CIEDE2000", r, [](const AgainstPolarised& a) { return a.p95DeltaE; },
        spp);
    md += formatText(
        "\nThe relative difference of a pixel is |Y_mode - Y_polarised| / ((Y_mode + "
        "Y_polarised) / 2), in [0, 2], over the pixels not black in both renders (%zu for the "
        "spectral render, %zu for the RGB render). Each compared pair shares its seed (common "
        "random numbers: the same paths, and for the spectral render the same wavelengths), so "
        "its difference carries far less noise than two independent renders would. Its noise is "
        "measured from a second pair of renders with another seed: per pixel and channel, n = "
        "((mode1 - polarised1) - (mode2 - polarised2)) / sqrt(2) has the variance of the first "
        "pair's difference and no true difference in it, and the noise floor is the same "
        "statistic between m + n/2 and m - n/2, m the mean of the two renders: two images that "
        "differ by that noise alone. A difference is resolved when it exceeds %g times its "
        "floor; the samples that would resolve one that does not are estimated with the noise "
        "falling as 1/sqrt(spp) and adding in quadrature to the true difference. The column "
        "beside each is the difference between the second pair: a difference that is real shows "
        "in both. Premises: the two pairs differ by their seed alone, and every sample number of "
        "the sampler changes with the seed (sobol-global, whose film positions do not, is "
        "refused). Where the RGB difference exceeds the spectral one, RGB mode's approximations "
        "cost more than ignoring polarisation.\n\n"
        "Spectral against polarised: ![relative difference](relative_difference.png) "
        "![CIEDE2000](ciede2000.png)\n\n"
        "RGB against polarised: ![relative difference](rgb_relative_difference.png) "
        "![CIEDE2000](rgb_ciede2000.png)\n\n",
        r.spectral.comparedPixels, r.rgb.comparedPixels, kResolvedOverFloor);
    md += formatText(
        "## The light's polarisation\n\n"
        "Degree of linear polarisation of the light reaching the camera, over the lit pixels: "
        "mean %.3f, max %.3f (noise: the mean |DoLP| difference to the second polarised render "
        "is %.3f; noise biases a small DoLP upwards). Angle of linear polarisation in the image "
        "frame (docs/polarisation.md, \"Stokes images\"), drawn where DoLP >= %g.\n\n"
        "![DoLP](dolp.png) ![AoLP](aolp.png)\n\n"
        "Files: polarised.exr (with the Stokes layers S0..S3), spectral.exr, rgb.exr.\n",
        r.meanDolp, r.maxDolp, r.dolpNoise, r.dolpThreshold);
    report.addSummary(md);
}

}  // namespace lamina::experiments
