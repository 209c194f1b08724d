#include "lamina/experiments/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "lamina/core/output_files.h"
#include "svg_text.h"

namespace lamina::experiments {

namespace {

constexpr double kPlotWidth = 520, kHeight = 480;
constexpr double kLeft = 80, kTop = 40, kBottom = 60;
// The legend right of the plot: a 30-unit line sample, then the name at about 7 units per
// character of the 12-unit font, so that no name is cut.
constexpr double kLegendSample = 42, kCharWidth = 7.2;
// About 8 units per character of the 14-unit title font.
constexpr double kTitleCharWidth = 8.0;
// A qualitative palette that stays distinguishable in print (Okabe and Ito 2008).
constexpr const char* kColors[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#F0E442", "#000000"};

struct Axis {
    bool log;
    double lo, hi;  // in axis units (log10 if log)
    double map(double v, double from, double to) const {
        const double a = log ? std::log10(v) : v;
        return from + (a - lo) / (hi - lo) * (to - from);
    }
    bool drawable(double v) const { return std::isfinite(v) && (!log || v > 0); }
    // Tick positions in data units: decades for log axes, a 1-2-5 step otherwise.
    std::vector<double> ticks() const {
        std::vector<double> t;
        if (log) {
            for (double e = std::ceil(lo - 1e-9); e <= hi + 1e-9; e += 1)
                t.push_back(std::pow(10, e));
            return t;
        }
        const double raw = (hi - lo) / 6, mag = std::pow(10, std::floor(std::log10(raw)));
        const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
        for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step)
            t.push_back(v);
        return t;
    }
};

Axis makeAxis(bool log, double lo, double hi) {
    if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
        lo = log ? 1 : 0;
        hi = log ? 10 : 1;
    }
    if (log) {
        lo = std::floor(std::log10(lo));
        hi = std::ceil(std::log10(hi));
        if (hi <= lo) hi = lo + 1;
    } else {
        const double pad = 0.05 * (hi - lo);
        lo -= pad;
        hi += pad;
    }
    return {log, lo, hi};
}

std::string format(double v) {
    if (std::abs(v) < 1e-12) v = 0;  // no "-0" from accumulated steps
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

void SvgPlot::write(const std::filesystem::path& path) const {
    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    for (const Series& s : series_)
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            if ((logX_ && s.x[i] <= 0) || (logY_ && s.y[i] <= 0)) continue;
            xlo = std::min(xlo, s.x[i]);
            xhi = std::max(xhi, s.x[i]);
            ylo = std::min(ylo, s.y[i]);
            yhi = std::max(yhi, s.y[i]);
        }
    const Axis ax = makeAxis(logX_, xlo, xhi), ay = makeAxis(logY_, ylo, yhi);
    std::size_t longest = 0;
    for (const Series& s : series_)
        longest = std::max(longest, s.name.size());
    // The title is centred over the plot unless it is wider: then the figure widens for it.
    const double titleHalf = 0.5 * kTitleCharWidth * double(title_.size());
    const double titleX = std::max(kLeft + kPlotWidth / 2, titleHalf + 10);
    const double width = std::max(
        kLeft + kPlotWidth + std::max(120.0, kLegendSample + 20 + kCharWidth * double(longest)),
        titleX + titleHalf + 10);
    const double x0 = kLeft, x1 = kLeft + kPlotWidth, y0 = kHeight - kBottom, y1 = kTop;

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\""
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << titleX << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
        << svgEscape(title_) << "</text>\n";
    for (double t : ax.ticks()) {
        const double x = ax.map(t, x0, x1);
        svg << "<line x1=\"" << x << "\" y1=\"" << y0 << "\" x2=\"" << x << "\" y2=\"" << y1
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << x << "\" y=\"" << y0 + 16
            << "\" text-anchor=\"middle\">" << format(t) << "</text>\n";
    }
    for (double t : ay.ticks()) {
        const double y = ay.map(t, y0, y1);
        svg << "<line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x1 << "\" y2=\"" << y
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << x0 - 6 << "\" y=\"" << y + 4
            << "\" text-anchor=\"end\">" << format(t) << "</text>\n";
    }
    svg << "<rect x=\"" << x0 << "\" y=\"" << y1 << "\" width=\"" << x1 - x0 << "\" height=\""
        << y0 - y1 << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << kHeight - 18
        << "\" text-anchor=\"middle\">" << svgEscape(xLabel_) << "</text>\n"
        << "<text transform=\"translate(20," << (y0 + y1) / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << svgEscape(yLabel_) << "</text>\n";
    for (std::size_t k = 0; k < series_.size(); ++k) {
        const Series& s = series_[k];
        const char* color = kColors[k % std::size(kColors)];
        std::ostringstream points;
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!ax.drawable(s.x[i]) || !ay.drawable(s.y[i])) continue;
            const double px = ax.map(s.x[i], x0, x1), py = ay.map(s.y[i], y0, y1);
            points << px << "," << py << " ";
            if (s.markers)
                svg << "<circle cx=\"" << px << "\" cy=\"" << py << "\" r=\"2.5\" fill=\"" << color
                    << "\"/>\n";
        }
        svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.8\""
            << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"" << points.str()
            << "\"/>\n";
        const double ly = y1 + 14 + 18 * double(k);
        svg << "<line x1=\"" << x1 + 12 << "\" y1=\"" << ly - 4 << "\" x2=\"" << x1 + 36
            << "\" y2=\"" << ly - 4 << "\" stroke=\"" << color << "\" stroke-width=\"2\""
            << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>\n<text x=\"" << x1 + 42
            << "\" y=\"" << ly << "\">" << svgEscape(s.name) << "</text>\n";
    }
    svg << "</svg>\n";
    writeTextFile(path, svg.str());
}

}  // namespace lamina::experiments
