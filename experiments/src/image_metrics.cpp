#include "lamina/experiments/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lamina/core/error.h"
#include "lamina/spectral/color_difference.h"

namespace lamina::experiments {

ImageMetrics compareImages(const render::RgbImage& a, const render::RgbImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw InputError("the images differ in size: " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    ImageMetrics m;
    double relSquares = 0;  // sum of the relMSE terms squared, for its standard error
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        if (!std::isfinite(d)) {
            ++m.nonFinite;
            continue;
        }
        m.mse += d * d;
        const double rel = d * d / (double(b.pixels[i]) * double(b.pixels[i]) + kRelMseEpsilon);
        m.relmse += rel;
        relSquares += rel * rel;
        m.mae += std::abs(d);
        m.max = std::max(m.max, std::abs(d));
        ++m.compared;
    }
    if (const std::size_t n = m.compared; n > 0) {
        m.mse /= double(n);
        m.relmse /= double(n);
        m.mae /= double(n);
        if (n > 1) {
            const double variance = std::max(
                0.0, (relSquares / double(n) - m.relmse * m.relmse) * double(n) / double(n - 1));
            m.relmseStandardError = std::sqrt(variance / double(n));
        }
    }
    m.rmse = std::sqrt(m.mse);
    return m;
}

namespace {

bool hasFiniteValue(const render::RgbImage& image) {
    return std::any_of(image.pixels.begin(), image.pixels.end(),
                       [](float v) { return std::isfinite(v); });
}

}  // namespace

void requireComparedValues(const ImageMetrics& m, const render::RgbImage& a,
                           const std::string& nameA, const render::RgbImage& reference,
                           const std::string& nameB) {
    if (m.compared > 0) return;
    for (const auto& [image, name] : {std::pair{&a, &nameA}, std::pair{&reference, &nameB}})
        if (!hasFiniteValue(*image))
            throw InputError(*name +
                             ": the image has no finite pixels (every value is NaN or "
                             "infinite): there is nothing to measure");
    throw InputError(nameA + " and " + nameB +
                     ": no channel value is finite in both images: there is nothing to measure");
}

std::string nonFiniteNote(const ImageMetrics& m) {
    if (m.nonFinite == 0) return "";
    return std::to_string(m.nonFinite) + " of " + std::to_string(m.nonFinite + m.compared) +
           " channel values are NaN or infinite in one of the images: the metrics are over the "
           "other " +
           std::to_string(m.compared);
}

double metricValue(const ImageMetrics& m, Metric metric) {
    switch (metric) {
        case Metric::Mse:
            return m.mse;
        case Metric::Rmse:
            return m.rmse;
        case Metric::Relmse:
            return m.relmse;
        case Metric::Mae:
            return m.mae;
        case Metric::Max:
            return m.max;
    }
    return m.mse;
}

namespace {
/// Mean over R, G, B of |a - b|, per pixel.
std::vector<float> meanAbsoluteDifference(const render::RgbImage& a, const render::RgbImage& b) {
    std::vector<float> d(std::size_t(a.width) * a.height);
    for (std::size_t p = 0; p < d.size(); ++p) {
        double sum = 0;
        for (int c = 0; c < 3; ++c)
            sum += std::abs(double(a.pixels[p * 3 + c]) - double(b.pixels[p * 3 + c])) / 3;
        d[p] = float(sum);
    }
    return d;
}
}  // namespace

MapFigure differenceFigure(const render::RgbImage& a, const render::RgbImage& b,
                           const std::string& title) {
    MapFigure map;
    map.title = title;
    map.quantity = "|difference|, mean over R, G, B";
    map.unit = "linear radiance";
    map.width = a.width;
    map.height = a.height;
    map.values = meanAbsoluteDifference(a, b);
    map.fromZero = true;
    return map;
}

ImagePair imagePair(const render::RgbImage& a, const std::string& labelA, const render::RgbImage& b,
                    const std::string& labelB, const std::string& title) {
    ImagePair pair;
    pair.title = title;
    pair.labelA = labelA;
    pair.labelB = labelB;
    pair.width = a.width;
    pair.height = a.height;
    pair.a = a.pixels;
    pair.b = b.pixels;
    return pair;
}

void writeDifferenceImage(const std::filesystem::path& path, const render::RgbImage& a,
                          const render::RgbImage& b, double scale) {
    const std::vector<float> difference = meanAbsoluteDifference(a, b);
    std::vector<float> rgb;
    rgb.reserve(difference.size() * 3);
    for (const float v : difference) {
        if (!std::isfinite(v)) {
            rgb.insert(rgb.end(), {0.5f, 0.5f, 0.5f});
            continue;
        }
        // A ramp whose brightness rises monotonically, readable in grey print too.
        const double t = std::clamp(double(v) / (scale > 0 ? scale : 1), 0.0, 1.0);
        rgb.insert(rgb.end(),
                   {float(std::clamp(2 * t - 0.5, 0.0, 1.0)),
                    float(std::clamp(2 * t - 1.0, 0.0, 1.0)), float(t < 0.5 ? 2 * t : 2 - 2 * t)});
    }
    render::writeRgb8(path, a.width, a.height, rgb);
}

std::vector<float> ciede2000Map(const render::RgbImage& a, const render::RgbImage& b) {
    std::vector<float> map(std::size_t(a.width) * a.height);
    for (std::size_t i = 0; i < map.size(); ++i) {
        const Rgb<double> ca(a.pixels[3 * i], a.pixels[3 * i + 1], a.pixels[3 * i + 2]);
        const Rgb<double> cb(b.pixels[3 * i], b.pixels[3 * i + 1], b.pixels[3 * i + 2]);
        map[i] = float(ciede2000Rec709(ca, cb));
    }
    return map;
}

double pixelLuminance(const render::RgbImage& image, std::size_t i) {
    return luminance(
        Rgb<double>(image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]));
}

std::vector<float> relativeDifferenceMap(const render::RgbImage& a, const render::RgbImage& b) {
    double brightest = 0;
    for (std::size_t i = 0; i < a.pixels.size() / 3; ++i)
        brightest = std::max({brightest, pixelLuminance(a, i), pixelLuminance(b, i)});
    const auto light = [&](double y) { return y > kNoLight * brightest ? y : 0.0; };
    std::vector<float> map(std::size_t(a.width) * a.height);
    for (std::size_t i = 0; i < map.size(); ++i) {
        const double ya = light(pixelLuminance(a, i)), yb = light(pixelLuminance(b, i));
        map[i] = ya + yb > 0 ? float(std::abs(ya - yb) / ((ya + yb) / 2)) : std::nanf("");
    }
    return map;
}

double meanOfFinite(const std::vector<float>& values) {
    double sum = 0;
    std::size_t n = 0;
    for (const float v : values)
        if (std::isfinite(v)) {
            sum += v;
            ++n;
        }
    return n == 0 ? 0 : sum / double(n);
}

double percentileOf(std::vector<float> values, double p) {
    std::erase_if(values, [](float v) { return !std::isfinite(v); });
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const double rank = std::clamp(p, 0.0, 100.0) / 100 * double(values.size() - 1);
    const std::size_t below = std::size_t(rank);
    const std::size_t above = std::min(below + 1, values.size() - 1);
    return double(values[below]) + (rank - double(below)) * double(values[above] - values[below]);
}

render::RgbImage filmImage(const render::Film& film) {
    render::RgbImage img;
    img.width = film.width();
    img.height = film.height();
    img.pixels.resize(std::size_t(img.width) * img.height * 3);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                img.pixels[(std::size_t(y) * img.width + x) * 3 + std::size_t(c)] = float(v[c]);
        }
    return img;
}

void ErrorLog::record(double seconds, int spp, const render::Film& film) {
    rows_.push_back({seconds, spp, compareImages(filmImage(film), reference_)});
}

std::string ErrorLog::csvHeader(const std::string& columns) {
    return (columns.empty() ? "" : columns + ",") + "seconds,spp,mse,relmse,mae\n";
}

std::string ErrorLog::csvRows(const std::string& prefix) const {
    std::string out;
    char line[256];
    for (const Row& r : rows_) {
        std::snprintf(line, sizeof line, "%.6g,%d,%.9g,%.9g,%.9g\n", r.seconds, r.spp,
                      r.metrics.mse, r.metrics.relmse, r.metrics.mae);
        out += (prefix.empty() ? "" : prefix + ",") + line;
    }
    return out;
}

}  // namespace lamina::experiments
