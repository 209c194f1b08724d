#include "lamina/scene/cloud_density.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/perlin_noise.h"

namespace lamina::render {

namespace {

constexpr int kOctaves = 5;
/// The noise sum's bound: 0.5 + 0.25 + ... + 0.5^5 = 0.96875 times the noise's.
constexpr double kSumBound = 0.96875 * double(kPerlinNoiseBound);

}  // namespace

float CloudDensity::at(const Vec3f& p) const {
    Vec3f q = frequency * p;
    if (wispiness > 0.0f) {
        // Two perturbations of the lookup point, the second finer and half as strong.
        float strength = 0.05f * wispiness, scale = 10.0f;
        for (int k = 0; k < 2; ++k) {
            q += strength * perlinNoiseDifferences(scale * q);
            strength *= 0.5f;
            scale *= 1.99f;
        }
    }
    float sum = 0.0f, weight = 0.5f, scale = 1.0f;
    for (int k = 0; k < kOctaves; ++k) {
        sum += weight * perlinNoise(scale * q);
        weight *= 0.5f;
        scale *= 1.99f;
    }
    const float noisy = std::clamp((1.0f - p.y) * 4.5f * density * sum, 0.0f, 1.0f);
    const float d = noisy + 2.0f * std::max(0.0f, 0.5f - p.y);
    return std::clamp(d, 0.0f, 1.0f);  // also a NaN density (a non-finite p) to 0
}

MajorantGrid CloudDensity::majorants(const Vec3f& boxMin, const Vec3f& boxMax) const {
    MajorantGrid m;
    m.nx = 1;
    m.ny = kLayers;
    m.nz = 1;
    m.maxima.resize(kLayers);
    const double lo = boxMin.y, height = double(boxMax.y) - double(boxMin.y);
    for (int layer = 0; layer < kLayers; ++layer) {
        // The layer widened by half a layer on each side: the walk assigns a point to a layer
        // by its ray parameter, which rounding may place just beyond the layer's faces.
        const double y0 = lo + height * (layer - 0.5) / kLayers;
        const double y1 = lo + height * (layer + 1.5) / kLayers;
        // |1 - y| is largest at an end of the layer; 0.5 - y at its bottom.
        const double lever = std::max(std::abs(1.0 - y0), std::abs(1.0 - y1));
        const double noisy = std::min(1.0, lever * 4.5 * double(density) * kSumBound * 1.001);
        const double bound = std::min(1.0, noisy + 2.0 * std::max(0.0, 0.5 - y0));
        m.maxima[std::size_t(layer)] = std::isfinite(bound) ? float(bound) : 1.0f;
    }
    return m;
}

}  // namespace lamina::render
