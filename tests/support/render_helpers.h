// Small scenes and image statistics for the end-to-end tests.
#pragma once

#include <string>

#include "lamina/render/renderer.h"

namespace lamina::testing {

inline render::SceneDesc sceneFromText(const std::string& json) {
    static const JsonSource source{"<test scene>", "."};
    return render::parseScene(json, source);
}

inline std::string sharedCornellBox() {
    return std::string(LAMINA_SOURCE_DIR) + "/scenes/cornell-box.json";
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

}  // namespace lamina::testing
