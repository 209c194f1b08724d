// Line plots written as SVG by the program itself (the experiments' figures need no Python):
// linear or logarithmic axes with decade ticks, one polyline per series, a legend.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lamina::experiments {

class SvgPlot {
  public:
    struct Series {
        std::string name;
        std::vector<double> x, y;
        bool dashed = false;
        bool markers = false;
    };

    SvgPlot(std::string title, std::string xLabel, std::string yLabel)
        : title_(std::move(title)), xLabel_(std::move(xLabel)), yLabel_(std::move(yLabel)) {}

    void setLogX(bool on) { logX_ = on; }
    void setLogY(bool on) { logY_ = on; }
    void add(Series s) { series_.push_back(std::move(s)); }
    /// Writes the plot; InputError if the file cannot be written. Points that cannot be
    /// drawn (non-finite, or <= 0 on a log axis) are skipped.
    void write(const std::filesystem::path& path) const;

  private:
    std::string title_, xLabel_, yLabel_;
    bool logX_ = false, logY_ = false;
    std::vector<Series> series_;
};

}  // namespace lamina::experiments
