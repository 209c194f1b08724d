#include "lamina/experiments/bsdf_plot.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "lamina/experiments/figure_drawing.h"

namespace lamina::experiments {

namespace {

// To three decimals, printed with ten significant digits as the scene readers print numbers
// (formatNumber, json_reader.h): 0.6, 36.87, -1.
std::string rounded(double v) {
    std::ostringstream s;
    s.precision(10);
    s << std::round(v * 1000) / 1000;
    return s.str();
}

constexpr int kHemisphereCells = 200;

}  // namespace

BsdfPlotFiles bsdfPlotFiles(const std::filesystem::path& output) {
    const std::filesystem::path directory =
        output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
    const std::string stem = output.stem().string();
    return {directory, stem, stem + "-hemisphere"};
}

std::vector<std::filesystem::path> BsdfPlotFiles::all() const {
    std::vector<std::filesystem::path> files;
    for (const std::string& stem : {plane, hemisphere})
        for (const char* suffix : {".figure.json", ".png", ".pdf"})
            files.push_back(directory / (stem + suffix));
    files.push_back(directory / (hemisphere + ".f32"));
    return files;
}

BsdfPlot plotBsdf(const std::function<double(const Vec3d& wi)>& value, const Vec3d& wo,
                  const std::string& material) {
    const std::string what =
        material + ", wo = (" + rounded(wo.x) + ", " + rounded(wo.y) + ", " + rounded(wo.z) + ")";
    const double tangential = std::hypot(wo.x, wo.y);
    const Vec3d u =
        tangential > 0 ? Vec3d(wo.x / tangential, wo.y / tangential, 0.0) : Vec3d(1.0, 0.0, 0.0);
    LineSeries lobe;
    lobe.name = "f cos theta_i";
    double peak = 0;
    for (int k = 0; k <= 720; ++k) {
        const double degrees = -180.0 + 0.5 * k, t = glm::radians(degrees);
        lobe.x.push_back(degrees);
        lobe.y.push_back(value(std::sin(t) * u + Vec3d(0.0, 0.0, std::cos(t))));
        peak = std::max(peak, lobe.y.back());
    }
    const double thetaO = glm::degrees(std::atan2(tangential, wo.z));
    const auto marker = [&](std::string name, double degrees, const char* colour) {
        LineSeries s;
        s.name = std::move(name);
        s.x = {degrees, degrees};
        s.y = {0.0, peak};
        s.style = LineSeries::Style::Dashed;
        s.colour = colour;
        return s;
    };
    LineFigure plane;
    plane.title = "Plane of incidence: " + what;
    plane.xLabel = "theta_i from the normal, towards (" + rounded(u.x) + ", " + rounded(u.y) +
                   ", 0) (degrees)";
    plane.yLabel = "f cos theta_i (1/sr)";
    // The lobe spans decades only where it is sharp; a linear axis shows its shape as drawn.
    plane.xScale = plane.yScale = AxisScale::Linear;
    plane.panels.push_back(
        {"",
         {lobe, marker("wo (theta_o = " + rounded(thetaO) + " deg)", thetaO, "grey"),
          marker("mirror direction", -thetaO, "black")},
         ""});

    constexpr int n = kHemisphereCells;
    std::vector<float> heat(std::size_t(n) * n, std::nanf(""));
    double hemispherePeak = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double px = (x + 0.5) / n * 2 - 1, py = 1 - (y + 0.5) / n * 2;
            const double r2 = px * px + py * py;
            if (r2 >= 1) continue;
            const double v = value(Vec3d(px, py, std::sqrt(1 - r2)));
            heat[std::size_t(y) * n + std::size_t(x)] = float(v);
            hemispherePeak = std::max(hemispherePeak, v);
        }
    const double edge = 1.0 - 1.0 / n;  // the centres of the outermost cells
    MapFigure hemisphere;
    hemisphere.title = "Upper hemisphere: " + what;
    hemisphere.quantity = "f cos theta_i";
    hemisphere.unit = "1/sr";
    hemisphere.width = hemisphere.height = n;
    hemisphere.values = std::move(heat);
    hemisphere.fromZero = true;
    // The peak as the map stores it (float): nothing lies beyond.
    hemisphere.upper = hemispherePeak > 0 ? double(float(hemispherePeak)) : 1.0;
    hemisphere.equalAspect = true;  // the disk stays round
    hemisphere.x = MapAxis{"wi.x (direction cosine)", -edge, edge, {}};
    hemisphere.y = MapAxis{"wi.y (direction cosine)", edge, -edge, {}};
    hemisphere.caption = "Cells outside the unit disk (below the horizon) are grey.";
    return {u, peak, hemispherePeak, std::move(plane), std::move(hemisphere)};
}

std::string writeBsdfPlot(const BsdfPlot& plot, const BsdfPlotFiles& files) {
    writeFigureSpec(files.directory, files.plane, plot.plane);
    writeFigureSpec(files.directory, files.hemisphere, plot.hemisphere);
    for (const std::string& stem : {files.plane, files.hemisphere})
        if (std::string note = drawFigures(files.directory / (stem + ".figure.json"));
            !note.empty())
            return note;
    return "";
}

}  // namespace lamina::experiments
