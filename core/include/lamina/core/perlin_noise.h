// Perlin's gradient noise in three dimensions (Perlin 2002, "Improving Noise", SIGGRAPH): a
// pseudo-random gradient at every integer lattice point, chosen by hashing the point through
// Perlin's published permutation of 0..255, and between lattice points the eight corners'
// linear ramps blended with the quintic 6t^5 - 15t^4 + 10t^3 (continuous second derivatives).
// Sums of octaves of it are in noise_sums.h.
#pragma once

#include "lamina/core/vector.h"

namespace lamina {

/// Noise at p: 0 at every integer lattice point, continuous, periodic with period 256 along
/// each axis. Coordinates are first reduced modulo 2^30 (as pbrt-v4's Noise, so that large
/// coordinates keep their lattice cell in an int); a non-finite coordinate gives 0.
float perlinNoise(const Vec3f& p);

/// |perlinNoise(p)| <= kPerlinNoiseBound everywhere: each corner's ramp g . (p - corner) has a
/// gradient g of two components +-1 and a third 0, and every component of p - corner lies in
/// [-1, 1], so |ramp| <= 2; the quintic weights lie in [0, 1], so the blend is a convex
/// combination of the eight ramps (and the implementation clamps each blend to its two ends,
/// so rounding cannot leave the bound either). Measured maxima are about 1.
inline constexpr float kPerlinNoiseBound = 2.0f;

/// pbrt-v4's DNoise: the forward differences of perlinNoise with step 0.01 along x, y and z,
/// divided by the step (an approximate gradient, used to perturb lookup points).
Vec3f perlinNoiseDifferences(const Vec3f& p);

}  // namespace lamina
