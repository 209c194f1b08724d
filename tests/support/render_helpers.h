// Small scenes and image statistics for the end-to-end tests.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"
#include "lamina/render/renderer.h"
#include "source_files.h"

namespace lamina::testing {

// One emitter of every kind (a triangle mesh, a rectangle, a disk, a sphere, a two-sided
// triangle), point, spot, directional and environment lights; the spot light faces away from
// some points and the one-sided triangle is seen from behind by others.
inline constexpr const char* kOneEmitterOfEveryKind = R"({
  "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
  "film": {"resolution": [8, 8]},
  "materials": {"m": {"type": "lambert", "reflectance": 0.5}},
  "shapes": [
    {"type": "mesh", "material": "m", "emission": {"radiance": [1, 2, 3]},
     "positions": [[0, 0, 0], [1, 0, 0], [0.2, 1.5, 0.3]], "faces": [[0, 1, 2]]},
    {"type": "rectangle", "material": "m", "emission": {"radiance": 2},
     "transform": [{"scale": [0.5, 0.25, 1]}, {"translate": [0, 2, 0]}]},
    {"type": "disk", "material": "m", "radius": 0.3, "emission": {"radiance": 1.5}},
    {"type": "sphere", "material": "m", "center": [3, 0, 0], "radius": 0.4,
     "emission": {"radiance": 0.7}},
    {"type": "mesh", "material": "m", "emission": {"radiance": 1, "two_sided": true},
     "positions": [[0, -2, 0], [1, -2, 0], [0, -2, 1]], "faces": [[0, 2, 1]]}
  ],
  "lights": [
    {"type": "point", "position": [0, 1, 0], "intensity": 3},
    {"type": "spot", "position": [0, 1, 0], "look_at": [0, 0, 0], "intensity": 2,
     "cone_angle": 30, "falloff_start": 20},
    {"type": "directional", "direction": [0, -1, 0.2], "irradiance": 1.2},
    {"type": "environment", "radiance": [0.2, 0.3, 0.4]}
  ]
})";

/// A test sky of w x h pixels, rows from the top: a gradient brightening upwards, a bright sun
/// (50) a third of the way across and a quarter down, and a black band in the lowest quarter.
inline std::vector<Rgb<float>> skyTestImage(int w, int h) {
    std::vector<Rgb<float>> px(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float v = 0.2f + 0.8f * float(h - y) / float(h);
            if (std::abs(x - w / 3) < 3 && std::abs(y - h / 4) < 2) v = 50.0f;
            if (y > 3 * h / 4) v = 0.0f;
            px[std::size_t(y) * w + x] = Rgb<float>(v, 0.8f * v, 0.6f * v);
        }
    return px;
}

inline render::SceneDesc sceneFromText(const std::string& json) {
    static const JsonSource source{"<test scene>", "."};
    return render::parseScene(json, source);
}

inline std::string sharedCornellBox() {
    return sourceFile("scenes/cornell-box.json").string();
}

/// Mean of a channel over the image and its standard error from the per-pixel variances
/// (pixels are independent estimates).
struct ImageMean {
    double mean = 0, standardError = 0;
};

inline ImageMean imageMean(const render::Film& film, int channel) {
    double sum = 0, var = 0;
    const double n = double(film.width()) * film.height();
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            sum += film.pixel(x, y)[channel];
            var += film.varianceOfMean(x, y);
        }
    return {sum / n, std::sqrt(var) / n};
}

/// The image mean of one channel with its standard error from that channel's own per-pixel
/// variances (Film::varianceOfMeanRgb): the luminance's variance (imageMean) understates the
/// red and blue channels', most in spectral mode, where sampled wavelengths add colour noise.
inline ImageMean channelMean(const render::Film& film, int channel) {
    double sum = 0, var = 0;
    const double n = double(film.width()) * film.height();
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            sum += film.pixel(x, y)[channel];
            var += film.varianceOfMeanRgb(x, y)[channel];
        }
    return {sum / n, std::sqrt(var) / n};
}

}  // namespace lamina::testing
