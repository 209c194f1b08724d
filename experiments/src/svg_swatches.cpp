#include "lamina/experiments/svg_swatches.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "lamina/core/output_files.h"
#include "svg_text.h"

namespace lamina::experiments {

namespace {

constexpr double kSwatch = 44, kGap = 4, kTop = 64, kBottom = 20;
// About 7.2 units per character of the 12-unit font, 8 of the 14-unit title.
constexpr double kCharWidth = 7.2, kTitleCharWidth = 8.0;

// The sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1].
double encodeSrgb(double linear) {
    const double l = std::clamp(linear, 0.0, 1.0);
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
}

std::string hexColour(const Rgb<double>& linear) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(255 * encodeSrgb(linear[0]))),
                  int(std::lround(255 * encodeSrgb(linear[1]))),
                  int(std::lround(255 * encodeSrgb(linear[2]))));
    return buf;
}

}  // namespace

void SvgSwatches::write(const std::filesystem::path& path) const {
    std::size_t longestRow = 0;
    for (const std::string& r : rows)
        longestRow = std::max(longestRow, r.size());
    // Row names right-aligned left of the grid; the y label rotated left of them.
    const double x0 = 40 + kCharWidth * double(longestRow) + 10;
    const double gridW = double(columns.size()) * (kSwatch + kGap) - kGap;
    const double gridH = double(rows.size()) * (kSwatch + kGap) - kGap;
    const double width = std::max(x0 + gridW + 20, kTitleCharWidth * double(title.size()) + 20);
    const double height = kTop + gridH + kBottom;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
        << svgEscape(title) << "</text>\n";
    for (std::size_t c = 0; c < columns.size(); ++c)
        svg << "<text x=\"" << x0 + double(c) * (kSwatch + kGap) + kSwatch / 2 << "\" y=\""
            << kTop - 8 << "\" text-anchor=\"middle\">" << svgEscape(columns[c]) << "</text>\n";
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double y = kTop + double(r) * (kSwatch + kGap);
        svg << "<text x=\"" << x0 - 8 << "\" y=\"" << y + kSwatch / 2 + 4
            << "\" text-anchor=\"end\">" << svgEscape(rows[r]) << "</text>\n";
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const std::size_t i = r * columns.size() + c;
            if (i >= colours.size()) break;
            svg << "<rect x=\"" << x0 + double(c) * (kSwatch + kGap) << "\" y=\"" << y
                << "\" width=\"" << kSwatch << "\" height=\"" << kSwatch << "\" fill=\""
                << hexColour(colours[i]) << "\" stroke=\"#888\"/>\n";
        }
    }
    svg << "<text x=\"" << x0 + gridW / 2 << "\" y=\"" << kTop - 28 << "\" text-anchor=\"middle\">"
        << svgEscape(xLabel) << "</text>\n"
        << "<text transform=\"translate(18," << kTop + gridH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << svgEscape(yLabel) << "</text>\n"
        << "</svg>\n";
    writeTextFile(path, svg.str());
}

}  // namespace lamina::experiments
