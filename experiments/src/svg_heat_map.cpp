#include "lamina/experiments/svg_heat_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "lamina/core/output_files.h"
#include "lamina/output/image_output.h"
#include "svg_text.h"

namespace lamina::experiments {

namespace {

constexpr double kMapSize = 400;  // the longer side of the map, in SVG units
// Maps with more cells than this (images rather than parameter grids) are drawn from a PNG.
constexpr std::size_t kMaxVectorCells = 64 * 64;
constexpr double kLeft = 90, kTop = 40, kBottom = 60, kBarWidth = 18, kBarGap = 24;

std::string number(double v) {
    if (std::abs(v) < 1e-12) v = 0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

std::string hex(const std::array<float, 3>& c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(255 * c[0])),
                  int(std::lround(255 * c[1])), int(std::lround(255 * c[2])));
    return buf;
}

/// 1-2-5 steps between lo and hi, about `count` of them.
std::vector<double> niceTicks(double lo, double hi, int count) {
    std::vector<double> t;
    if (!(hi > lo)) return {lo};
    const double raw = (hi - lo) / count, mag = std::pow(10, std::floor(std::log10(raw)));
    const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
        t.push_back(v);
    return t;
}

}  // namespace

std::array<float, 3> falseColour(Palette palette, double t) {
    if (palette == Palette::Diverging) {
        t = std::clamp(t, -1.0, 1.0);
        const float s = float(std::sqrt(std::abs(t)));
        return t > 0 ? std::array<float, 3>{s, 0, 0} : std::array<float, 3>{0, 0, s};
    }
    t = std::clamp(t, 0.0, 1.0);
    return {float(std::clamp(2 * t - 0.5, 0.0, 1.0)), float(std::clamp(2 * t - 1.0, 0.0, 1.0)),
            float(t < 0.5 ? 2 * t : 2 - 2 * t)};
}

SvgHeatMap::SvgHeatMap(std::string title, int width, int height, std::vector<float> values)
    : title_(std::move(title)), width_(width), height_(height), values_(std::move(values)) {
    x_ = {"x (pixels)", 0, double(width - 1), {}};
    y_ = {"y (pixels)", 0, double(height - 1), {}};
}

void SvgHeatMap::setAxes(Axis x, Axis y) {
    x_ = std::move(x);
    y_ = std::move(y);
}

void SvgHeatMap::setScale(Palette palette, double lo, double hi, std::string label) {
    palette_ = palette;
    lo_ = lo;
    hi_ = hi > lo ? hi : lo + 1;
    scaleLabel_ = std::move(label);
}

std::array<float, 3> SvgHeatMap::colourOf(float v) const {
    if (!std::isfinite(v)) return {0.5f, 0.5f, 0.5f};
    const double t =
        palette_ == Palette::Diverging ? double(v) / hi_ : (double(v) - lo_) / (hi_ - lo_);
    return falseColour(palette_, t);
}

void SvgHeatMap::writePng(const std::filesystem::path& path) const {
    std::vector<float> rgb;
    rgb.reserve(values_.size() * 3);
    for (float v : values_)
        for (float c : colourOf(v))
            rgb.push_back(c);
    render::writeRgb8(path, width_, height_, rgb);
}

void SvgHeatMap::write(const std::filesystem::path& path,
                       const std::optional<std::filesystem::path>& png) const {
    const double cell = kMapSize / std::max(width_, height_);
    const double mapW = cell * width_, mapH = cell * height_;
    const double x0 = kLeft, y0 = kTop, barX = x0 + mapW + kBarGap;
    // The bar's numbers (at most "-0.000123") and its rotated label fit in 80 units; a long
    // title (about 8 units per character at 14 units) widens the figure.
    const double barEnd = barX + kBarWidth + 80;
    const double totalW = std::max(barEnd, 8.0 * double(title_.size()) + 20);
    const double totalH = y0 + mapH + kBottom;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\""
        << totalW << "\" height=\"" << totalH << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << totalW / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
        << svgEscape(title_) << "</text>\n";
    if (png || std::size_t(width_) * std::size_t(height_) > kMaxVectorCells) {
        // The map as a PNG (same colours, one pixel per cell) that the figure shows: an
        // image-sized map as vector cells would take megabytes.
        const std::filesystem::path raster =
            png ? *png : std::filesystem::path(path).replace_extension(".png");
        writePng(raster);
        const std::filesystem::path parent = std::filesystem::path(path).parent_path();
        const std::string href = svgEscape(
            raster.parent_path() == parent ? raster.filename().string() : raster.string());
        svg << "<image x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << mapW << "\" height=\""
            << mapH << "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\""
            << href << "\" xlink:href=\"" << href << "\"/>\n";
    } else {
        // A small grid: runs of equal colour per row as rectangles.
        const auto colourAt = [&](float v) { return hex(colourOf(v)); };
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_;) {
                const std::string c = colourAt(values_[std::size_t(y) * width_ + x]);
                int end = x + 1;
                while (end < width_ && colourAt(values_[std::size_t(y) * width_ + end]) == c)
                    ++end;
                svg << "<rect x=\"" << x0 + cell * x << "\" y=\"" << y0 + cell * y << "\" width=\""
                    << cell * (end - x) + 0.05 << "\" height=\"" << cell + 0.05 << "\" fill=\"" << c
                    << "\"/>\n";
                x = end;
            }
    }
    svg << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << mapW << "\" height=\"" << mapH
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    // Axes: category names at every cell, or 1-2-5 ticks of the value range.
    const auto ticks = [&](const Axis& a, int cells, bool horizontal) {
        const auto at = [&](double pos) {  // pos: cell index (centre), may be fractional
            return (horizontal ? x0 : y0) + cell * (pos + 0.5);
        };
        std::vector<std::pair<double, std::string>> out;
        if (!a.categories.empty()) {
            // Every k-th name, so that neighbouring names do not overlap (about 7 units per
            // character across, one 14-unit line down).
            std::size_t longest = 0;
            for (const std::string& c : a.categories)
                longest = std::max(longest, c.size());
            const double room = horizontal ? 7.0 * double(longest) + 6 : 14;
            const int every = std::max(1, int(std::ceil(room / cell)));
            for (int i = 0; i < cells && i < int(a.categories.size()); i += every)
                out.emplace_back(at(i), a.categories[std::size_t(i)]);
        } else if (cells == 1 || a.last == a.first) {
            out.emplace_back(at(0), number(a.first));
        } else {
            const double lo = std::min(a.first, a.last), hi = std::max(a.first, a.last);
            for (double v : niceTicks(lo, hi, 5))
                out.emplace_back(at((v - a.first) / (a.last - a.first) * (cells - 1)), number(v));
        }
        return out;
    };
    for (const auto& [px, text] : ticks(x_, width_, true))
        svg << "<line x1=\"" << px << "\" y1=\"" << y0 + mapH << "\" x2=\"" << px << "\" y2=\""
            << y0 + mapH + 5 << "\" stroke=\"black\"/>\n<text x=\"" << px << "\" y=\""
            << y0 + mapH + 18 << "\" text-anchor=\"middle\">" << svgEscape(text) << "</text>\n";
    for (const auto& [py, text] : ticks(y_, height_, false))
        svg << "<line x1=\"" << x0 - 5 << "\" y1=\"" << py << "\" x2=\"" << x0 << "\" y2=\"" << py
            << "\" stroke=\"black\"/>\n<text x=\"" << x0 - 8 << "\" y=\"" << py + 4
            << "\" text-anchor=\"end\">" << svgEscape(text) << "</text>\n";
    svg << "<text x=\"" << x0 + mapW / 2 << "\" y=\"" << y0 + mapH + 40
        << "\" text-anchor=\"middle\">" << svgEscape(x_.label) << "</text>\n"
        << "<text transform=\"translate(18," << y0 + mapH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << svgEscape(y_.label) << "</text>\n";
    // The colour bar: hi at the top, with its numbers and its label.
    constexpr int kSteps = 64;
    const double lo = palette_ == Palette::Diverging ? -hi_ : lo_;
    for (int k = 0; k < kSteps; ++k) {
        const double f = (k + 0.5) / kSteps;  // 0 at the bottom
        const double t = palette_ == Palette::Diverging ? 2 * f - 1 : f;
        svg << "<rect x=\"" << barX << "\" y=\"" << y0 + mapH * (1 - double(k + 1) / kSteps)
            << "\" width=\"" << kBarWidth << "\" height=\"" << mapH / kSteps + 0.05 << "\" fill=\""
            << hex(falseColour(palette_, t)) << "\"/>\n";
    }
    svg << "<rect x=\"" << barX << "\" y=\"" << y0 << "\" width=\"" << kBarWidth << "\" height=\""
        << mapH << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double v : niceTicks(lo, hi_, 6)) {
        const double py = y0 + mapH * (1 - (v - lo) / (hi_ - lo));
        svg << "<line x1=\"" << barX + kBarWidth << "\" y1=\"" << py << "\" x2=\""
            << barX + kBarWidth + 4 << "\" y2=\"" << py << "\" stroke=\"black\"/>\n<text x=\""
            << barX + kBarWidth + 7 << "\" y=\"" << py + 4 << "\">" << number(v) << "</text>\n";
    }
    svg << "<text transform=\"translate(" << barEnd - 10 << "," << y0 + mapH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << svgEscape(scaleLabel_) << "</text>\n"
        << "</svg>\n";
    writeTextFile(path, svg.str());
}

}  // namespace lamina::experiments
