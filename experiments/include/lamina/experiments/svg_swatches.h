// A grid of colour swatches as an SVG figure that stands alone: a title, every row and column
// named, and the names of both axes. Each swatch is its true colour (sRGB-encoded for the
// display), not a false colour: the figure compares what models look like.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lamina/core/spectrum.h"

namespace lamina::experiments {

struct SvgSwatches {
    std::string title;
    std::string xLabel, yLabel;  ///< what the columns and the rows are, with units
    std::vector<std::string> columns, rows;
    std::vector<Rgb<double>> colours;  ///< linear Rec.709, row-major from the top row

    /// Writes the figure (complete or not at all); InputError if it cannot be written.
    void write(const std::filesystem::path& path) const;
};

}  // namespace lamina::experiments
