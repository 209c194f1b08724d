// A figure's data as the figure module draws it (python/lamina/figures.py, docs/figures.md):
// NAME.figure.json in the report's directory, with a map's values beside it in NAME.f32
// (little-endian float32, row-major from the top row). The experiments say what a figure
// shows (its quantity, unit, whether it is signed); the module chooses the scale from the data
// (a sequential or diverging colour map, limits at a percentile, log where values span decades).
// Beside them, the pairs of images an experiment compared, for its report page's viewer
// (python/lamina/report_page.py): NAME.pair.json with NAME.a.f32 and NAME.b.f32.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lamina/core/spectrum.h"

namespace lamina::experiments {

/// An axis scale: chosen by the module from the data (log where positive values span a factor
/// of 100 or more), or fixed.
enum class AxisScale { Auto, Linear, Log };

struct LineSeries {
    std::string name;  ///< the legend's entry; empty: none
    std::vector<double> x, y;
    std::vector<double> standardError;  ///< empty or one per point: drawn as a band around y
    enum class Style { Solid, Dashed, Dotted } style = Style::Solid;
    bool markers = false;
    std::string colour;  ///< a matplotlib colour; empty: the next of the cycle
};

/// One set of axes of a line figure.
struct LinePanel {
    std::string title;  ///< above the panel (a figure of several panels)
    std::vector<LineSeries> series;
    std::string xLabel;  ///< empty: the figure's
};

/// Line plots side by side sharing the y axis (one panel: a plain plot), or in a grid of
/// `columns` panels a row sharing both axes (a Mueller matrix's 4 x 4 elements).
struct LineFigure {
    std::string title, xLabel, yLabel;  ///< the labels with their units
    std::string caption;                ///< printed under the figure
    std::vector<LinePanel> panels;
    int columns = 0;  ///< panels per row; 0: all in one row
    AxisScale xScale = AxisScale::Auto, yScale = AxisScale::Auto;
};

/// A map's axis with the values at the centres of its first and last cells (columns left to
/// right, rows top to bottom), or one category name per cell.
struct MapAxis {
    std::string label;
    double first = 0, last = 0;
    std::vector<std::string> categories;
};

/// A false-colour map of one value per cell (NaN: no value, drawn grey).
struct MapFigure {
    std::string title, caption;
    std::string quantity, unit;  ///< the colour bar's label: "quantity (unit)"
    int width = 0, height = 0;
    std::vector<float> values;  ///< width x height, row-major from the top row
    /// Unsigned: a sequential map (viridis) between percentiles of the values, or from 0
    /// (`fromZero`, a distance such as CIEDE2000). Signed: a diverging map symmetric about 0.
    bool isSigned = false;
    bool fromZero = false;
    double percentile = 99;       ///< the upper limit (and 100 - it the lower)
    std::optional<double> upper;  ///< a fixed upper limit instead (the caption says so)
    /// A cyclic quantity (an angle) of this period [lo, hi]: a cyclic map (twilight) over it,
    /// whose ends are one colour, as the quantity's are; no percentiles.
    std::optional<std::pair<double, double>> cycle;
    std::optional<MapAxis> x, y;  ///< none: the axes are the image's pixels
    bool equalAspect = false;     ///< x and y in one unit: drawn with equal scales
    std::string clipReason;       ///< why more than 5% of the values may lie beyond the limits
};

/// A map of one value per pixel of a `width` x `height` image (row-major from the top row),
/// titled `title`, its colour bar labelled `quantity`: the per-pixel maps of the experiments that
/// compare renders.
MapFigure pixelMapFigure(std::vector<float> values, int width, int height, std::string title,
                         std::string quantity);

/// A grid of true colours (not a false-colour map): what models look like side by side.
struct SwatchFigure {
    std::string title, xLabel, yLabel;
    std::vector<std::string> columns, rows;
    std::vector<Rgb<double>> colours;  ///< linear Rec.709, row-major from the top row
};

/// Two images an experiment compared, shown in its report page's viewer (A/B, exposure,
/// zoom, difference, relative error, values under the cursor).
struct ImagePair {
    std::string title, caption;
    std::string labelA, labelB;  ///< what each image is ("RGB mode", "reference", ...)
    int width = 0, height = 0;
    std::vector<float> a, b;  ///< linear Rec.709 RGB interleaved, row-major from the top row
};

/// Writes DIRECTORY/NAME.figure.json (and NAME.f32 for a map); InputError if it cannot.
void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const LineFigure& figure);
void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const MapFigure& figure);
void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const SwatchFigure& figure);
/// Writes DIRECTORY/NAME.pair.json with NAME.a.f32 and NAME.b.f32; InputError if it cannot.
void writeImagePairSpec(const std::filesystem::path& directory, const std::string& name,
                        const ImagePair& pair);

}  // namespace lamina::experiments
