#include "lamina/experiments/figure_spec.h"

#include <bit>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "lamina/core/error.h"
#include "lamina/core/output_files.h"

namespace lamina::experiments {

namespace {

using nlohmann::json;

// The module's spec version (figures.py SPEC_VERSION).
constexpr int kSpecVersion = 1;
// The page's pair spec version (report_page.py PAIR_VERSION).
constexpr int kPairVersion = 1;

/// A number of a series; JSON has no NaN: null, which the module reads as a missing point.
json number(double v) {
    return std::isfinite(v) ? json(v) : json(nullptr);
}

json numbers(const std::vector<double>& values) {
    json a = json::array();
    for (const double v : values)
        a.push_back(number(v));
    return a;
}

const char* scaleName(AxisScale s) {
    switch (s) {
        case AxisScale::Linear:
            return "linear";
        case AxisScale::Log:
            return "log";
        case AxisScale::Auto:
            break;
    }
    return "auto";
}

json series(const LineSeries& s) {
    json j = {{"name", s.name}, {"x", numbers(s.x)}, {"y", numbers(s.y)}, {"markers", s.markers}};
    if (!s.standardError.empty()) j["se"] = numbers(s.standardError);
    j["style"] = s.style == LineSeries::Style::Dashed   ? "dashed"
                 : s.style == LineSeries::Style::Dotted ? "dotted"
                                                        : "solid";
    if (!s.colour.empty()) j["color"] = s.colour;
    return j;
}

json axis(const MapAxis& a) {
    json j = {{"label", a.label}, {"first", number(a.first)}, {"last", number(a.last)}};
    if (!a.categories.empty()) j["categories"] = a.categories;
    return j;
}

json header(const char* kind, const std::string& title) {
    return {{"lamina_figure", kSpecVersion}, {"kind", kind}, {"title", title}};
}

void writeSpec(const std::filesystem::path& directory, const std::string& name, const json& j) {
    writeTextFile(directory / (name + ".figure.json"), j.dump(1) + "\n");
}

/// Little-endian float32 values, whole or not at all (NAME.f32 of a map, the images of a pair).
void writeFloat32(const std::filesystem::path& path, const std::vector<float>& values) {
    static_assert(std::endian::native == std::endian::little, "the .f32 files are little-endian");
    TemporaryFile tmp(path);
    std::ofstream out(tmp.path(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(values.data()),
              std::streamsize(values.size() * sizeof(float)));
    out.close();
    if (!out) throw InputError(path.string() + ": cannot be written");
    tmp.commit();
}

}  // namespace

void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const LineFigure& figure) {
    json j = header("lines", figure.title);
    j["x_label"] = figure.xLabel;
    j["y_label"] = figure.yLabel;
    j["log_x"] = scaleName(figure.xScale);
    j["log_y"] = scaleName(figure.yScale);
    if (!figure.caption.empty()) j["caption"] = figure.caption;
    json panels = json::array();
    for (const LinePanel& p : figure.panels) {
        json s = json::array();
        for (const LineSeries& one : p.series)
            s.push_back(series(one));
        json panel = {{"title", p.title}, {"series", s}};
        if (!p.xLabel.empty()) panel["x_label"] = p.xLabel;
        panels.push_back(panel);
    }
    j["panels"] = panels;
    if (figure.columns > 0) j["columns"] = figure.columns;
    writeSpec(directory, name, j);
}

void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const MapFigure& figure) {
    if (figure.width <= 0 || figure.height <= 0 ||
        figure.values.size() != std::size_t(figure.width) * std::size_t(figure.height))
        throw std::logic_error("MapFigure " + name + ": values do not fill width x height");
    const std::filesystem::path data = directory / (name + ".f32");
    writeFloat32(data, figure.values);
    json j = header("map", figure.title);
    j["data"] = data.filename().string();
    j["width"] = figure.width;
    j["height"] = figure.height;
    j["quantity"] = figure.quantity;
    j["unit"] = figure.unit;
    j["signed"] = figure.isSigned;
    j["from_zero"] = figure.fromZero;
    j["percentile"] = figure.percentile;
    if (figure.upper) j["upper"] = number(*figure.upper);
    if (figure.cycle) j["cycle"] = {number(figure.cycle->first), number(figure.cycle->second)};
    if (figure.x) j["x_axis"] = axis(*figure.x);
    if (figure.y) j["y_axis"] = axis(*figure.y);
    if (figure.equalAspect) j["equal_aspect"] = true;
    if (!figure.caption.empty()) j["caption"] = figure.caption;
    if (!figure.clipReason.empty()) j["clip_reason"] = figure.clipReason;
    writeSpec(directory, name, j);
}

void writeFigureSpec(const std::filesystem::path& directory, const std::string& name,
                     const SwatchFigure& figure) {
    json j = header("swatches", figure.title);
    j["x_label"] = figure.xLabel;
    j["y_label"] = figure.yLabel;
    j["columns"] = figure.columns;
    j["rows"] = figure.rows;
    json colours = json::array();
    for (const Rgb<double>& c : figure.colours)
        colours.push_back({number(c[0]), number(c[1]), number(c[2])});
    j["colours"] = colours;
    writeSpec(directory, name, j);
}

void writeImagePairSpec(const std::filesystem::path& directory, const std::string& name,
                        const ImagePair& pair) {
    const std::size_t values = std::size_t(pair.width) * std::size_t(pair.height) * 3;
    if (pair.width <= 0 || pair.height <= 0 || pair.a.size() != values || pair.b.size() != values)
        throw std::logic_error("ImagePair " + name + ": the images do not fill width x height");
    writeFloat32(directory / (name + ".a.f32"), pair.a);
    writeFloat32(directory / (name + ".b.f32"), pair.b);
    const json j = {
        {"lamina_pair", kPairVersion}, {"title", pair.title},    {"caption", pair.caption},
        {"label_a", pair.labelA},      {"label_b", pair.labelB}, {"width", pair.width},
        {"height", pair.height},       {"a", name + ".a.f32"},   {"b", name + ".b.f32"}};
    writeTextFile(directory / (name + ".pair.json"), j.dump(1) + "\n");
}

MapFigure pixelMapFigure(std::vector<float> values, int width, int height, std::string title,
                         std::string quantity) {
    MapFigure map;
    map.title = std::move(title);
    map.quantity = std::move(quantity);
    map.width = width;
    map.height = height;
    map.values = std::move(values);
    return map;
}

}  // namespace lamina::experiments
