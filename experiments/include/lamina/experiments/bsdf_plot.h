// The figures of `lamina bsdf plot`: a BSDF's f cos theta_i for one outgoing direction wo,
// along the plane of incidence (the normal and wo's tangential direction u; x when wo is the
// normal) and as a false-colour map over the upper hemisphere with its colour bar. Two figures
// of the figure module (figure_spec.h, docs/figures.md): NAME.png and NAME-hemisphere.png,
// each also as PDF, with their data beside them.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "lamina/core/vector.h"
#include "lamina/experiments/figure_spec.h"

namespace lamina::experiments {

/// The figures' stems in their directory: NAME and NAME-hemisphere of `output` (NAME.png).
struct BsdfPlotFiles {
    std::filesystem::path directory;
    std::string plane, hemisphere;
    /// Every file the figures write (the specs, the map's data, the PNGs and PDFs).
    std::vector<std::filesystem::path> all() const;
};

BsdfPlotFiles bsdfPlotFiles(const std::filesystem::path& output);

struct BsdfPlot {
    Vec3d tangent;  ///< u, the plane's direction along the surface
    double planePeak = 0, hemispherePeak = 0;
    LineFigure plane;
    MapFigure hemisphere;
};

/// `value(wi)`: what is drawn, f(wo, wi) |cos theta_i| as one number per direction (wi in the
/// local frame, z = the normal); `material` names the material and its mode in the titles.
/// The plane: theta_i in [-180, 180] degrees in steps of 0.5, positive towards u (wo at
/// +theta_o, its mirror direction at -theta_o); the hemisphere: 200 x 200 cells seen from
/// above, wi = (x, y, sqrt(1 - x^2 - y^2)), +y at the top, cells outside the disk grey.
BsdfPlot plotBsdf(const std::function<double(const Vec3d& wi)>& value, const Vec3d& wo,
                  const std::string& material);

/// Writes both figures' specs and draws them; returns "" or the note why they were not drawn.
std::string writeBsdfPlot(const BsdfPlot& plot, const BsdfPlotFiles& files);

}  // namespace lamina::experiments
