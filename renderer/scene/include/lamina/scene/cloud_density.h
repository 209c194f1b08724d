// pbrt-v4's procedural `cloud` medium's density (docs/media.md, "Procedural clouds"): sums of
// Perlin noise (perlin_noise.h) that thin out with altitude, evaluated exactly at every lookup,
// with majorants that bound it by an interval argument (no grid of samples in between).
#pragma once

#include "lamina/core/vector.h"
#include "lamina/scene/density_grid.h"

namespace lamina::render {

/// The density of pbrt-v4's CloudMedium (its Density method, media.h) at a point p of the
/// medium's space, in [0, 1]:
///   q = frequency p, then, if wispiness > 0, twice q += a_k D(b_k q) with a = 0.05 wispiness,
///   0.025 wispiness and b = 10, 19.9 (D: pbrt-v4's forward-difference gradient of the noise,
///   perlinNoiseDifferences), which makes the edges wispy;
///   s = sum over k = 0..4 of 0.5^(k+1) noise(1.99^k q) (an fBm of five octaves, Perlin 1985);
///   d = clamp((1 - p.y) 4.5 density s, 0, 1) + 2 max(0, 0.5 - p.y), clamped to [0, 1]
/// (so the cloud is solid below y = 0 and thins out with altitude; above y = 1 the factor
/// 1 - p.y turns negative and the noise's troughs give density instead).
struct CloudDensity {
    float density = 1.0f;    ///< scales the noise sum (pbrt-v4's "density")
    float wispiness = 1.0f;  ///< the perturbation's strength; <= 0: none
    float frequency = 5.0f;  ///< the noise's frequency per unit of medium space

    float at(const Vec3f& p) const;

    /// Majorants over the box [boxMin, boxMax]: kLayers layers along y (the density's bound
    /// depends on y alone), each the largest value the formula above can take in the layer
    /// for any noise within +-kPerlinNoiseBound (so |s| <= 0.96875 kPerlinNoiseBound), at
    /// most 1.
    MajorantGrid majorants(const Vec3f& boxMin, const Vec3f& boxMax) const;
    static constexpr int kLayers = 64;
};

}  // namespace lamina::render
