// The report of `lamina fresnel`: per material MATERIAL.csv, MATERIAL_spectral.csv, the
// figures MATERIAL (reflectance per channel) and MATERIAL_swatches; with a scene, its renders,
// the difference and the CIEDE2000 map; and summary.md.
#include <cmath>
#include <sstream>

#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"
#include "lamina/spectral/color_space.h"

namespace lamina::experiments {

namespace {

void writeCsvs(const FresnelMaterial& m, const Report& report) {
    std::ostringstream csv;
    csv << "degrees";
    for (const FresnelModel& model : m.models)
        for (const char* ch : {"R", "G", "B"})
            csv << ",\"" << model.name << " " << ch << "\"";
    csv << "\n";
    for (int a = 0; a < kFresnelAngles; ++a) {
        csv << a;
        for (const FresnelModel& model : m.models)
            for (int ch = 0; ch < 3; ++ch)
                csv << "," << model.rgb[std::size_t(a)][ch];
        csv << "\n";
    }
    TablePlot models;
    models.title = "Fresnel reflectance of " + m.name + ": the RGB models";
    models.x = "degrees";
    models.xLabel = "angle of incidence (degrees)";
    models.yLabel = "reflectance per channel (linear Rec.709)";
    report.writeTable(m.stem + ".csv", csv.str(), models);

    std::ostringstream spec;
    spec << "degrees";
    for (const WavelengthCurve& c : m.spectral)
        spec << "," << int(c.nm) << "nm";
    spec << "\n";
    for (int a = 0; a < kFresnelAngles; ++a) {
        spec << a;
        for (const WavelengthCurve& c : m.spectral)
            spec << "," << c.reflectance[std::size_t(a)];
        spec << "\n";
    }
    TablePlot exact;
    exact.title = "Fresnel reflectance of " + m.name + ": exact, per wavelength";
    exact.x = "degrees";
    exact.xLabel = "angle of incidence (degrees)";
    exact.yLabel = "reflectance";
    report.writeTable(m.stem + "_spectral.csv", spec.str(), exact);
}

/// One panel per channel (R, G, B of linear Rec.709): every model's reflectance against angle,
/// the exact colour's first, and the exact reflectance at the channel's wavelength (650, 550
/// and 450 nm) dotted. Luminance alone would hide what the models get wrong: the colour.
void writePlot(const FresnelMaterial& m, Report& report) {
    LineFigure figure;
    figure.title = "Fresnel reflectance of " + m.name + " per channel: exact and RGB models";
    figure.xLabel = "angle of incidence (degrees)";
    figure.yLabel = "reflectance (linear Rec.709 channel, under D65)";
    figure.xScale = figure.yScale = AxisScale::Linear;
    const char* channels[] = {"R", "G", "B"};
    for (int ch = 0; ch < 3; ++ch) {
        LinePanel panel{std::string(channels[ch]) + " channel", {}};
        for (std::size_t k = 0; k < m.models.size(); ++k) {
            const FresnelModel& model = m.models[k];
            LineSeries s{model.name, {}, {}};
            if (k == 0) s.colour = "black";
            for (int a = 0; a < kFresnelAngles; ++a) {
                s.x.push_back(a);
                s.y.push_back(model.rgb[std::size_t(a)][ch]);
            }
            panel.series.push_back(std::move(s));
        }
        // m.plotted is 450, 550, 650 nm: the B, G and R channels' wavelengths.
        if (m.plotted.size() == 3) {
            const WavelengthCurve& c = m.plotted[std::size_t(2 - ch)];
            LineSeries s{ch == 0 ? "exact at 650, 550, 450 nm (R, G, B)" : "", {}, {}};
            s.style = LineSeries::Style::Dotted;
            s.colour = "0.35";
            for (int a = 0; a < kFresnelAngles; ++a) {
                s.x.push_back(a);
                s.y.push_back(c.reflectance[std::size_t(a)]);
            }
            panel.series.push_back(std::move(s));
        }
        figure.panels.push_back(std::move(panel));
    }
    figure.caption =
        "The exact curve is the colour of the spectral reflectance (380-780 nm) "
        "under D65; each RGB model is built from it as RGB mode builds it.";
    report.addFigure(m.stem, figure);
}

/// Rows: the models (the exact spectral reflectance's colour, and the RGB-mode models built
/// from it); columns: a few angles of incidence.
void writeSwatches(const FresnelMaterial& m, Report& report) {
    const int angles[] = {0, 30, 60, 75, 82, 87};
    SwatchFigure s;
    s.title = "Fresnel reflectance of " + m.name + " seen as a colour (" + m.stem +
              ", under D65, sRGB display)";
    s.xLabel = "angle of incidence (degrees)";
    s.yLabel = "model";
    for (int a : angles)
        s.columns.push_back(std::to_string(a));
    for (std::size_t row = 0; row < m.models.size(); ++row) {
        // The first model is the exact spectral curve (its colour); the others are RGB mode's.
        s.rows.push_back(row == 0 ? m.models[row].name : m.models[row].name + " (RGB mode)");
        for (int a : angles)
            s.colours.push_back(m.models[row].rgb[std::size_t(a)]);
    }
    report.addFigure(m.stem + "_swatches", s);
}

std::string table(const FresnelMaterial& m) {
    std::ostringstream md;
    md << "### " << m.stem << "\n\n"
       << "| model | max abs error | mean abs error | max CIEDE2000 | mean CIEDE2000 |\n"
       << "|---|---|---|---|---|\n";
    for (std::size_t i = 1; i < m.models.size(); ++i) {
        const FresnelModel& model = m.models[i];
        md << formatText("| %s | %.4f | %.4f | %.2f | %.2f |\n", model.name.c_str(), model.maxError,
                         model.meanError, model.maxDeltaE, model.meanDeltaE);
    }
    md << "\n![" << m.stem << " reflectance per channel](" << m.stem << ".png)\n\n![" << m.stem
       << " swatches](" << m.stem << "_swatches.png)\n\n";
    return md.str();
}

std::string writeScene(const FresnelSceneComparison& c, Report& report) {
    render::ImageMetadata meta;
    meta.ints["spp"] = c.rgb.spp;
    render::writeExr(report.file("scene_rgb.exr"), *c.rgb.film, false, meta);
    render::writeExr(report.file("scene_spectral.exr"), *c.spectral.film, false, meta);
    const render::RgbImage a = filmImage(*c.rgb.film), b = filmImage(*c.spectral.film);
    report.addImagePair("scene",
                        imagePair(a, "RGB mode", b, "spectral mode",
                                  "The scene in RGB and in spectral mode (" + c.scene + ")"));
    report.addFigure(
        "scene_difference",
        differenceFigure(a, b, "|RGB - spectral mode| of each pixel (" + c.scene + ")"));
    render::writeFloatExr(report.file("scene_ciede2000.exr"), a.width, a.height, {"Y"},
                          c.ciede2000);
    MapFigure map;
    map.title = "CIEDE2000 of each pixel, RGB against spectral mode (" + c.scene + ")";
    map.quantity = "CIEDE2000";
    map.width = a.width;
    map.height = a.height;
    map.values = c.ciede2000;
    map.fromZero = true;  // a distance: never negative, 0 is agreement
    map.caption = "Both renders' noise included.";
    report.addFigure("scene_ciede2000", map);
    const int spp = c.rgb.spp;
    const NoiseFloorReading meanReading = readAgainstFloor(c.meanDeltaE, c.floorMeanDeltaE, spp);
    const NoiseFloorReading p95Reading = readAgainstFloor(c.p95DeltaE, c.floorP95DeltaE, spp);
    return formatText(
               "### The scene in both modes: %s\n\n%d spp each (path integrator), %dx%d. RGB "
               "mode against spectral mode: relMSE %.4g, MAE %.4g; CIEDE2000 max %.2f.\n\n"
               "| CIEDE2000, RGB against spectral | value (noise floor) | with the second seed "
               "|\n|---|---|---|\n"
               "| mean | %s | %.2f |\n| 95th percentile | %s | %.2f |\n\n",
               c.scene.c_str(), spp, a.width, a.height, c.metrics.relmse, c.metrics.mae,
               c.maxDeltaE, describeReading(meanReading, spp).c_str(), c.otherSeedMeanDeltaE,
               describeReading(p95Reading, spp).c_str(), c.otherSeedP95DeltaE) +
           formatText(
               "The two modes are rendered with the same seed (common random numbers: the same "
               "pixel samples), so their difference carries far less noise than two independent "
               "renders would. Its noise is measured from a second pair of renders with another "
               "seed: per pixel and channel, n = ((rgb1 - spectral1) - (rgb2 - spectral2)) / "
               "sqrt(2) has the variance of the first pair's difference and no true difference "
               "in it, and the noise floor is the same statistic between m + n/2 and m - n/2, m "
               "the mean of the two renders: two images that differ by that noise alone. A "
               "difference is resolved when it exceeds %g times its floor; the samples that "
               "would resolve one that does not are estimated with the noise falling as "
               "1/sqrt(spp) and adding in quadrature to the true difference. The last column is "
               "the difference between the second pair: a difference that is real shows in "
               "both. Premises: the two pairs differ by their seed alone, and every sample "
               "number of the sampler changes with the seed (sobol-global, whose film positions "
               "do not, is refused).\n\n"
               "![CIEDE2000 map](scene_ciede2000.png) "
               "![|RGB - spectral|](scene_difference.png)\n\n",
               kResolvedOverFloor);
}

}  // namespace

void writeFresnelReport(const FresnelResult& result, Report& report) {
    std::string md =
        "# Fresnel: exact spectral against RGB models\n\n"
        "Reflectance of a flat interface from air, 0 to 89 degrees; errors are against the "
        "colour (linear Rec.709, under D65) of the exact spectral reflectance; the RGB models "
        "are built from that colour (F0, and F82 at cos = 1/7) as RGB mode builds them. These "
        "tables are computed from the n/k data in closed form, not sampled: they carry no "
        "noise, and need no floor.\n\n";
    if (result.thinFilmNm > 0)
        md += formatText(
            "Every material carries a thin film %g nm thick of index %g: the exact reflectance is "
            "the film's Airy sum per wavelength; RGB mode's film is Belcour and Barla's closed "
            "form with the channels' indices; F82 is the bare material's, for scale.\n\n",
            result.thinFilmNm, result.thinFilmIor);
    for (const FresnelMaterial& m : result.materials) {
        writeCsvs(m, report);
        writePlot(m, report);
        writeSwatches(m, report);
        md += table(m);
    }
    if (result.scene) md += writeScene(*result.scene, report);
    report.addSummary(md);
}

}  // namespace lamina::experiments
