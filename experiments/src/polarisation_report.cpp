// The report of `lamina polarisation`: the two renders (EXR; the polarised one with its Stokes
// layers), the images as a pair for the report page, the relative difference, CIEDE2000, DoLP
// and AoLP figures, and summary.md.
#include <cmath>

#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/polarisation.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

MapFigure pixelMap(const PolarisationResult& r, std::vector<float> values, std::string title,
                   std::string quantity) {
    MapFigure map;
    map.title = std::move(title) + " (" + r.scene + ")";
    map.quantity = std::move(quantity);
    map.width = r.width;
    map.height = r.height;
    map.values = std::move(values);
    return map;
}

void writeDifferenceFigures(const PolarisationResult& r, Report& report) {
    MapFigure relative =
        pixelMap(r, r.relative, "Relative difference of the luminance, spectral against polarised",
                 "|Y spectral - Y polarised| / mean Y");
    relative.fromZero = true;
    relative.upper = 2.0;  // the quantity's whole range: the same colours in every report
    relative.caption =
        "Symmetric relative difference, 0 to 2; grey: black in both renders. Both "
        "renders' noise included.";
    report.addFigure("relative_difference", relative);

    MapFigure de = pixelMap(r, r.ciede2000, "CIEDE2000 of each pixel, spectral against polarised",
                            "CIEDE2000");
    de.fromZero = true;  // a distance: never negative, 0 is agreement
    de.caption = "Both renders' noise included.";
    report.addFigure("ciede2000", de);
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

std::string row(const char* what, const FlooredStatistic& s, int spp) {
    return formatText("| %s | %s | %.2f |\n", what,
                      describeReading(readAgainstFloor(s.value, s.floor, spp), spp).c_str(),
                      s.otherSeed);
}

FlooredStatistic percent(const FlooredStatistic& s) {
    return {100 * s.value, 100 * s.floor, 100 * s.otherSeed};
}

}  // namespace

void writePolarisationReport(const PolarisationResult& r, Report& report) {
    render::ImageMetadata meta;
    meta.ints["spp"] = r.polarised.spp;
    render::writeExr(report.file("polarised.exr"), *r.polarised.film, false, meta);
    render::writeExr(report.file("spectral.exr"), *r.spectral.film, false, meta);
    render::writePngPreview(report.file("polarised.png"), *r.polarised.film, 0.0);
    render::writePngPreview(report.file("spectral.png"), *r.spectral.film, 0.0);
    const render::RgbImage p = filmImage(*r.polarised.film), s = filmImage(*r.spectral.film);
    report.addImagePair("renders", imagePair(p, "polarised mode", s, "spectral mode",
                                             "The scene in the polarised and in the spectral "
                                             "mode (" +
                                                 r.scene + ")"));
    writeDifferenceFigures(r, report);
    writePolarisationFigures(r, report);

    const int spp = r.polarised.spp;
    std::string md = formatText(
        "# Polarisation: what ignoring it costs in %s\n\n"
        "The scene rendered in the polarised mode (a Stokes vector per wavelength, a Mueller "
        "matrix at every event) and in the spectral mode (s and p averaged at every event), "
        "with the same seed, %d spp each (%s integrator), %dx%d. The spectral render is "
        "compared with the polarised one, the reference: relMSE %.4g, MAE %.4g.\n\n"
        "![polarised mode](polarised.png) ![spectral mode](spectral.png)\n\n"
        "| spectral against polarised | value (noise floor) | with the second seed |\n"
        "|---|---|---|\n",
        r.scene.c_str(), spp,
        std::string(render::kIntegratorNames.name(r.polarised.settings.integrator)).c_str(),
        r.width, r.height, r.metrics.relmse, r.metrics.mae);
    md += row("mean relative difference of the luminance (%)", percent(r.meanRelative), spp);
    md += row("95th percentile of the relative difference (%)", percent(r.p95Relative), spp);
    md += row("mean CIEDE2000", r.meanDeltaE, spp);
    md += row("95th percentile of CIEDE2000", r.p95DeltaE, spp);
    md += formatText(
        "\nThe relative difference of a pixel is |Y_spectral - Y_polarised| / ((Y_spectral + "
        "Y_polarised) / 2), in [0, 2], over the %zu pixels not black in both renders. The two "
        "compared renders share their seed (common random numbers: the same paths and "
        "wavelengths), so their difference carries far less noise than two independent renders "
        "would. Its noise is measured from a second pair of renders with another seed: per "
        "pixel and channel, n = ((spectral1 - polarised1) - (spectral2 - polarised2)) / "
        "sqrt(2) has the variance of the first pair's difference and no true difference in "
        "it, and the noise floor is the same statistic between m + n/2 and m - n/2, m the mean "
        "of the two renders: two images that differ by that noise alone. A difference is resolved "
        "when it exceeds %g times "
        "its floor; the samples that would resolve one that does not are estimated with the "
        "noise falling as 1/sqrt(spp) and adding in quadrature to the true difference. The "
        "last column is the difference between the second pair: a difference that is real "
        "shows in both. Premises: the two pairs differ by their seed alone, and every sample "
        "number of the sampler changes with the seed (sobol-global, whose film positions do "
        "not, is refused).\n\n"
        "![relative difference](relative_difference.png) ![CIEDE2000](ciede2000.png)\n\n",
        r.comparedPixels, kResolvedOverFloor);
    md += formatText(
        "## The light's polarisation\n\n"
        "Degree of linear polarisation of the light reaching the camera, over the lit pixels: "
        "mean %.3f, max %.3f (noise: the mean |DoLP| difference to the second polarised render "
        "is %.3f; noise biases a small DoLP upwards). Angle of linear polarisation in the image "
        "frame (docs/polarisation.md, \"Stokes images\"), drawn where DoLP >= %g.\n\n"
        "![DoLP](dolp.png) ![AoLP](aolp.png)\n\n"
        "Files: polarised.exr (with the Stokes layers S0..S3), spectral.exr.\n",
        r.meanDolp, r.maxDolp, r.dolpNoise, r.dolpThreshold);
    report.addSummary(md);
}

}  // namespace lamina::experiments
