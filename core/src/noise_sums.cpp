#include "lamina/core/noise_sums.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/perlin_noise.h"

namespace lamina {

namespace {

/// The octaves' frequency ratio (pbrt-v4's FBm and Turbulence).
constexpr float kLacunarity = 1.99f;

/// 3t^2 - 2t^3 of t = (x - a) / (b - a) clamped to [0, 1].
float smoothStep(float x, float a, float b) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float noiseOctaves(const Vec3f& dpdx, const Vec3f& dpdy, int maxOctaves) {
    const float top = float(std::max(maxOctaves, 0));
    const float len2 = std::max(lengthSquared(dpdx), lengthSquared(dpdy));
    if (len2 == 0.0f) return top;
    const float n = -1.0f - std::log2(len2) / 2.0f;
    if (!(n > 0.0f)) return 0.0f;  // also a NaN footprint
    return std::min(n, top);
}

float fbm(const Vec3f& p, const Vec3f& dpdx, const Vec3f& dpdy, float omega, int maxOctaves) {
    const float n = noiseOctaves(dpdx, dpdy, maxOctaves);
    const int whole = int(n);
    float sum = 0.0f, lambda = 1.0f, o = 1.0f;
    for (int i = 0; i < whole; ++i) {
        sum += o * perlinNoise(lambda * p);
        lambda *= kLacunarity;
        o *= omega;
    }
    return sum + o * smoothStep(n - float(whole), 0.3f, 0.7f) * perlinNoise(lambda * p);
}

float turbulence(const Vec3f& p, const Vec3f& dpdx, const Vec3f& dpdy, float omega,
                 int maxOctaves) {
    const float n = noiseOctaves(dpdx, dpdy, maxOctaves);
    const int whole = int(n);
    float sum = 0.0f, lambda = 1.0f, o = 1.0f;
    for (int i = 0; i < whole; ++i) {
        sum += o * std::abs(perlinNoise(lambda * p));
        lambda *= kLacunarity;
        o *= omega;
    }
    sum +=
        o * lerp(smoothStep(n - float(whole), 0.3f, 0.7f), 0.2f, std::abs(perlinNoise(lambda * p)));
    for (int i = whole; i < maxOctaves; ++i) {
        sum += o * 0.2f;
        o *= omega;
    }
    return sum;
}

float noiseSumBound(float omega, int maxOctaves) {
    float sum = 0.0f, o = 1.0f;
    for (int i = 0; i <= std::max(maxOctaves, 0); ++i) {
        sum += o;
        o *= std::abs(omega);
    }
    return (kPerlinNoiseBound + 0.2f) * sum;
}

}  // namespace lamina
