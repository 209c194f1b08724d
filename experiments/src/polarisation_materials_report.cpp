// The report of `lamina polarisation MATERIAL...` (polarisation_materials.h): per material a CSV
// of every number, the 4 x 4 Mueller elements, the reflectances, the diattenuation and the
// retardance against angle, and summary.md with the angles found per wavelength.
#include <cmath>
#include <sstream>

#include "lamina/experiments/polarisation_materials.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

namespace {

std::string elementName(int i, int j) {
    return "M" + std::to_string(i) + std::to_string(j);
}

std::string wavelengthLabel(const MuellerCurve& c) {
    return formatText("%g nm", c.nm);
}

/// Long format: one row per wavelength and angle, so that a table tool groups by nm.
void writeCsv(const PolarisationMaterial& m, const std::vector<double>& degrees,
              const Report& report) {
    std::ostringstream csv;
    csv.precision(10);
    csv << "nm,degrees,Rs,Rp,reflectance,diattenuation,retardance_degrees";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            csv << "," << elementName(i, j);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (i + j > 0) csv << "," << elementName(i, j) << "_over_M00";
    csv << "\n";
    for (const MuellerCurve& c : m.curves)
        for (std::size_t a = 0; a < degrees.size(); ++a) {
            const MuellerMatrix<double>& mm = c.mueller[a];
            csv << c.nm << "," << degrees[a] << "," << c.rs[a] << "," << c.rp[a] << "," << mm(0, 0)
                << "," << c.diattenuation[a] << "," << c.retardance[a];
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    csv << "," << mm(i, j);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    if (i + j > 0) csv << "," << (mm(0, 0) > 0 ? mm(i, j) / mm(0, 0) : 0.0);
            csv << "\n";
        }
    TablePlot plot;
    plot.title = "Specular reflection of " + m.name + " per wavelength";
    plot.x = "degrees";
    plot.y = {"Rs", "Rp", "reflectance"};
    plot.groupBy = {"nm"};
    plot.xLabel = "angle of incidence (degrees)";
    plot.yLabel = "reflectance";
    report.writeTable(m.stem + "_mueller.csv", csv.str(), plot);
}

/// One series per wavelength of `value(curve, angle index)`.
template <typename Value>
std::vector<LineSeries> perWavelength(const PolarisationMaterial& m,
                                      const std::vector<double>& degrees, Value value,
                                      bool named = true) {
    std::vector<LineSeries> out;
    for (const MuellerCurve& c : m.curves) {
        LineSeries s{named ? wavelengthLabel(c) : "", degrees, {}};
        for (std::size_t a = 0; a < degrees.size(); ++a)
            s.y.push_back(value(c, a));
        out.push_back(std::move(s));
    }
    return out;
}

void writeMuellerFigure(const PolarisationMaterial& m, const std::vector<double>& degrees,
                        Report& report) {
    LineFigure f;
    f.title = "Mueller matrix of specular reflection on " + m.name +
              " from air: M00 and the normalised elements";
    f.xLabel = "incidence (degrees)";
    f.yLabel = "M00, or Mij / M00";
    f.xScale = f.yScale = AxisScale::Linear;
    f.columns = 4;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            LinePanel p;
            p.title = i + j == 0 ? "M00 = (Rs + Rp) / 2" : elementName(i, j) + " / M00";
            p.series = perWavelength(
                m, degrees,
                [&](const MuellerCurve& c, std::size_t a) {
                    const MuellerMatrix<double>& mm = c.mueller[a];
                    if (i + j == 0) return mm(0, 0);
                    return mm(0, 0) > 0 ? mm(i, j) / mm(0, 0) : 0.0;
                },
                i + j == 0);
            f.panels.push_back(std::move(p));
        }
    f.caption =
        "Frames with x = s on the incident and the reflected ray (docs/polarisation.md). "
        "M01 / M00 is the diattenuation; M22 / M00 = M33 / M00 and M23 / M00 = -M32 / M00 are the "
        "cosine and sine of the retardance times sqrt(1 - diattenuation^2); the other eight "
        "elements are 0.";
    report.addFigure(m.stem + "_mueller", f);
}

void writeDerivedFigures(const PolarisationMaterial& m, const std::vector<double>& degrees,
                         Report& report) {
    LineFigure r;
    r.title = "Reflectance of " + m.name + " from air, s and p and unpolarised";
    r.xLabel = "angle of incidence (degrees)";
    r.yLabel = "reflectance";
    r.xScale = r.yScale = AxisScale::Linear;
    r.panels = {
        {"Rs = |r_s|^2",
         perWavelength(m, degrees, [](const MuellerCurve& c, std::size_t a) { return c.rs[a]; })},
        {"Rp = |r_p|^2",
         perWavelength(
             m, degrees, [](const MuellerCurve& c, std::size_t a) { return c.rp[a]; }, false)},
        {"(Rs + Rp) / 2 = M00",
         perWavelength(
             m, degrees, [](const MuellerCurve& c, std::size_t a) { return c.mueller[a](0, 0); },
             false)}};
    report.addFigure(m.stem + "_reflectance", r);

    // One panel against angle, a series per wavelength of `of(curve)`.
    const auto onePanel = [&](const std::string& name, std::string title, std::string yLabel,
                              const std::vector<double> MuellerCurve::*of, std::string caption) {
        LineFigure f;
        f.title = std::move(title) + " of reflection on " + m.name;
        f.xLabel = "angle of incidence (degrees)";
        f.yLabel = std::move(yLabel);
        f.xScale = f.yScale = AxisScale::Linear;
        f.panels = {{"", perWavelength(m, degrees, [&](const MuellerCurve& c, std::size_t a) {
                         return (c.*of)[a];
                     })}};
        f.caption = std::move(caption);
        report.addFigure(m.stem + "_" + name, f);
    };
    onePanel("diattenuation", "Diattenuation", "(Rs - Rp) / (Rs + Rp)",
             &MuellerCurve::diattenuation, "");
    onePanel("retardance", "Retardance", "phase of r_s conj(r_p) (degrees)",
             &MuellerCurve::retardance,
             "atan2(M23, M22): 180 degrees at normal incidence, 0 at grazing incidence.");
}

std::string angleTable(const PolarisationMaterial& m) {
    // The heading is the data's own name, with the files' stem where the name does not start
    // with it (an n/k file's).
    std::string md = "### " + m.name +
                     (m.name.rfind(m.stem, 0) == 0 ? "" : " (files " + m.stem + "_*)") + "\n\n";
    md += m.conductor
              ? "| wavelength | n + ik | principal angle (retardance 90 degrees) | "
                "minimum of Rp (pseudo-Brewster) | Rs, Rp there |\n|---|---|---|---|---|\n"
              : "| wavelength | n | Brewster's angle (M22 = 0) | minimum of Rp | Rs, Rp there | "
                "atan(n) |\n|---|---|---|---|---|---|\n";
    for (const MuellerCurve& c : m.curves) {
        const std::string principal =
            c.principalAngle ? formatText("%.4f", *c.principalAngle) : std::string("none");
        const MuellerMatrix<double> there = specularReflectionMueller(c.index, c.minimumRpAngle);
        const std::string reflectances =
            formatText("%.4f, %.3g", there(0, 0) + there(0, 1), c.minimumRp);
        if (m.conductor)
            md += formatText("| %g nm | %.4f + %.4fi | %s | %.4f | %s |\n", c.nm, c.index.real(),
                             c.index.imag(), principal.c_str(), c.minimumRpAngle,
                             reflectances.c_str());
        else
            md += formatText("| %g nm | %.4f | %s | %.4f | %s | %.4f |\n", c.nm, c.index.real(),
                             principal.c_str(), c.minimumRpAngle, reflectances.c_str(),
                             degrees(std::atan(c.index.real())));
    }
    md += "\n![" + m.stem + " Mueller matrix](" + m.stem + "_mueller.png)\n\n![" + m.stem +
          " reflectance](" + m.stem + "_reflectance.png)\n\n![" + m.stem + " diattenuation](" +
          m.stem + "_diattenuation.png) ![" + m.stem + " retardance](" + m.stem +
          "_retardance.png)\n\n";
    return md;
}

}  // namespace

void writePolarisationMaterialsReport(const PolarisationMaterialsResult& r, Report& report) {
    std::string md = formatText(
        "# Polarisation of specular reflection\n\n"
        "The Mueller matrix of reflection from air on each material against the angle of "
        "incidence, 0 to 90 degrees in steps of %g, in lamina's convention (docs/polarisation.md: "
        "x = s on both rays). Its first element M00 = (Rs + Rp) / 2 is the unpolarised "
        "reflectance the RGB and spectral modes use; the rest is what they leave out: the "
        "diattenuation M01 / M00 = (Rs - Rp) / (Rs + Rp), how strongly unpolarised light comes "
        "out polarised along s, and the retardance, the phase of r_s conj(r_p), which turns "
        "linear into elliptical polarisation.\n\n"
        "The angles below are found from the data: the principal angle where M22 = Re(r_s "
        "conj(r_p)) changes sign (for a dielectric r_s conj(r_p) is real and this is Brewster's "
        "angle, where r_p = 0 and the retardance jumps from 180 to 0 degrees; for a metal the "
        "retardance passes 90 degrees), and the minimum of Rp, each located on the table and "
        "refined by bisection or golden-section search of the same function. Every number is "
        "in STEM_mueller.csv (one row per wavelength and angle).\n\n",
        kMuellerAngleStep);
    for (const PolarisationMaterial& m : r.materials) {
        writeCsv(m, r.degrees, report);
        writeMuellerFigure(m, r.degrees, report);
        writeDerivedFigures(m, r.degrees, report);
        md += angleTable(m);
    }
    report.addSummary(md);
}

}  // namespace lamina::experiments
