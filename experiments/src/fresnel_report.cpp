// The report of `lamina fresnel`: per material MATERIAL.csv, MATERIAL_spectral.csv,
// MATERIAL.svg and MATERIAL_swatches.svg; with a scene, its renders and difference maps; and
// summary.md.
#include <cmath>
#include <sstream>

#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/svg_heat_map.h"
#include "lamina/experiments/svg_plot.h"
#include "lamina/experiments/svg_swatches.h"
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

/// Luminance of each model against angle, and the exact curve at three wavelengths.
void writePlot(const FresnelMaterial& m, const Report& report) {
    SvgPlot plot("Fresnel reflectance: " + m.name, "angle of incidence (degrees)",
                 "reflectance (luminance)");
    for (const FresnelModel& model : m.models) {
        SvgPlot::Series s{model.name, {}, {}};
        for (int a = 0; a < kFresnelAngles; ++a) {
            s.x.push_back(a);
            s.y.push_back(luminance(model.rgb[std::size_t(a)]));
        }
        plot.add(std::move(s));
    }
    for (const WavelengthCurve& c : m.plotted) {
        SvgPlot::Series s{"exact at " + std::to_string(int(c.nm)) + " nm", {}, {}, true};
        for (int a = 0; a < kFresnelAngles; ++a) {
            s.x.push_back(a);
            s.y.push_back(c.reflectance[std::size_t(a)]);
        }
        plot.add(std::move(s));
    }
    report.writeFigure(m.stem + ".svg", plot);
}

/// Rows: the models (the exact spectral reflectance's colour, and the RGB-mode models built
/// from it); columns: a few angles of incidence.
void writeSwatches(const FresnelMaterial& m, const Report& report) {
    const int angles[] = {0, 30, 60, 75, 82, 87};
    SvgSwatches s;
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
    s.write(report.file(m.stem + "_swatches.svg"));
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
    md << "\n![" << m.stem << " reflectance](" << m.stem << ".svg)\n\n![" << m.stem << " swatches]("
       << m.stem << "_swatches.svg)\n\n";
    return md.str();
}

std::string writeScene(const FresnelSceneComparison& c, const Report& report) {
    render::ImageMetadata meta;
    meta.ints["spp"] = c.rgb.spp;
    render::writeExr(report.file("scene_rgb.exr"), *c.rgb.film, false, meta);
    render::writeExr(report.file("scene_spectral.exr"), *c.spectral.film, false, meta);
    const render::RgbImage a = filmImage(*c.rgb.film), b = filmImage(*c.spectral.film);
    writeDifferenceImage(report.file("scene_difference.png"), a, b, c.metrics.max);
    render::writeFloatExr(report.file("scene_ciede2000.exr"), a.width, a.height, {"Y"},
                          c.ciede2000);
    SvgHeatMap map("CIEDE2000, RGB against spectral mode", a.width, a.height, c.ciede2000);
    map.setScale(Palette::Diverging, -10, 10, "CIEDE2000 (saturated at 10)");
    map.write(report.file("scene_ciede2000.svg"), report.file("scene_ciede2000.png"));
    return formatText(
        "### The scene in both modes: %s\n\n%d spp each (path integrator). RGB mode "
        "against spectral mode: relMSE %.4g, MAE %.4g; CIEDE2000 mean %.2f, max %.2f "
        "(noise included: both renders are noisy).\n\n"
        "![CIEDE2000 map, red = 10](scene_ciede2000.svg) "
        "![|RGB - spectral|](scene_difference.svg)\n\n",
        c.scene.c_str(), c.rgb.spp, c.metrics.relmse, c.metrics.mae, c.meanDeltaE, c.maxDeltaE);
}

}  // namespace

void writeFresnelReport(const FresnelResult& result, Report& report) {
    std::string md =
        "# Fresnel: exact spectral against RGB models\n\n"
        "Reflectance of a flat interface from air, 0 to 89 degrees; errors are against the "
        "colour (linear Rec.709, under D65) of the exact spectral reflectance; the RGB models "
        "are built from that colour (F0, and F82 at cos = 1/7) as RGB mode builds them.\n\n";
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
