// False-colour maps as SVG figures that stand alone: a title, the map itself, named axes with
// tick values, and a colour bar with numbers. A small grid (a parameter sweep) is drawn as
// rectangles, one per run of equal colour in a row; an image-sized map is written as a PNG
// beside the figure (same stem, same palette, one pixel per cell) that the figure shows, so
// the PNG can also be read alone with the figure's colour bar.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lamina::experiments {

enum class Palette {
    Sequential,  ///< 0 .. 1: black, blue, magenta, yellow, white
    Diverging,   ///< -1 .. 1: blue, black at 0, red (square-root ramp: small values show)
};

/// The colour of t (clamped to the palette's domain), RGB in [0, 1].
std::array<float, 3> falseColour(Palette palette, double t);

class SvgHeatMap {
  public:
    /// An axis of the map: its name with the unit, and the values at the centres of the
    /// first and last cells (columns left to right, rows top to bottom), or category names
    /// (one per cell) that replace the numbers.
    struct Axis {
        std::string label;
        double first = 0, last = 0;
        std::vector<std::string> categories;
    };

    /// `values`: width x height, row-major from the top row; NaN cells are drawn grey.
    SvgHeatMap(std::string title, int width, int height, std::vector<float> values);
    void setAxes(Axis x, Axis y);
    /// The colour bar: `lo` and `hi` are the ends of the palette (for Diverging, lo = -hi).
    void setScale(Palette palette, double lo, double hi, std::string label);
    /// The SVG figure. With `png`, the map is also written there and the figure shows it;
    /// without, an image-sized map goes to the PNG of the figure's stem beside it.
    void write(const std::filesystem::path& path,
               const std::optional<std::filesystem::path>& png = std::nullopt) const;

  private:
    /// The map alone as an 8-bit image, one pixel per cell, the same colours.
    void writePng(const std::filesystem::path& path) const;
    std::array<float, 3> colourOf(float value) const;
    std::string title_;
    int width_, height_;
    std::vector<float> values_;
    Axis x_, y_;
    Palette palette_ = Palette::Sequential;
    double lo_ = 0, hi_ = 1;
    std::string scaleLabel_;
};

}  // namespace lamina::experiments
