#include "lamina/experiments/bsdf_plot.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

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

BsdfPlotFiles bsdfPlotFiles(const std::filesystem::path& plane) {
    std::filesystem::path hemisphere = plane;
    hemisphere.replace_filename(plane.stem().string() + "-hemisphere.svg");
    return {plane, hemisphere, std::filesystem::path(hemisphere).replace_extension(".png")};
}

BsdfPlot plotBsdf(const std::function<double(const Vec3d& wi)>& value, const Vec3d& wo,
                  const std::string& material) {
    const std::string what =
        material + ", wo = (" + rounded(wo.x) + ", " + rounded(wo.y) + ", " + rounded(wo.z) + ")";
    const double tangential = std::hypot(wo.x, wo.y);
    const Vec3d u =
        tangential > 0 ? Vec3d(wo.x / tangential, wo.y / tangential, 0.0) : Vec3d(1.0, 0.0, 0.0);
    SvgPlot::Series lobe{"f cos theta_i", {}, {}};
    double peak = 0;
    for (int k = 0; k <= 720; ++k) {
        const double degrees = -180.0 + 0.5 * k, t = glm::radians(degrees);
        lobe.x.push_back(degrees);
        lobe.y.push_back(value(std::sin(t) * u + Vec3d(0.0, 0.0, std::cos(t))));
        peak = std::max(peak, lobe.y.back());
    }
    const double thetaO = glm::degrees(std::atan2(tangential, wo.z));
    SvgPlot plane("Plane of incidence: " + what,
                  "theta_i from the normal, towards (" + rounded(u.x) + ", " + rounded(u.y) +
                      ", 0) (degrees)",
                  "f cos theta_i (1/sr)");
    plane.add(std::move(lobe));
    plane.add({"wo (theta_o = " + rounded(thetaO) + " deg)", {thetaO, thetaO}, {0.0, peak}, true});
    plane.add({"mirror direction", {-thetaO, -thetaO}, {0.0, peak}, true});

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
    SvgHeatMap hemisphere("Upper hemisphere: " + what, n, n, std::move(heat));
    hemisphere.setAxes({"wi.x (direction cosine)", -edge, edge},
                       {"wi.y (direction cosine)", edge, -edge});
    hemisphere.setScale(Palette::Sequential, 0, hemispherePeak > 0 ? hemispherePeak : 1,
                        "f cos theta_i (1/sr)");
    return {u, peak, hemispherePeak, std::move(plane), std::move(hemisphere)};
}

void writeBsdfPlot(const BsdfPlot& plot, const BsdfPlotFiles& files) {
    plot.plane.write(files.plane);
    plot.hemisphere.write(files.hemisphere, files.hemispherePng);
}

}  // namespace lamina::experiments
