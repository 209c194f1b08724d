// Sums of octaves of Perlin noise (perlin_noise.h): fractional Brownian motion and turbulence
// (Perlin 1985, "An image synthesizer", SIGGRAPH: the sum of noise at doubling frequencies and
// halving amplitudes, and of its absolute value), antialiased as pbrt-v4's FBm and Turbulence
// (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 10.6): the number
// of octaves follows the lookup's footprint, and the last, partial octave fades in.
#pragma once

#include "lamina/core/vector.h"

namespace lamina {

/// How many octaves a footprint of (dpdx, dpdy) resolves, in [0, maxOctaves]: octave i has
/// frequency about 2^i, which aliases once its period falls below two footprints, so
/// n = -1 - log2(max(|dpdx|, |dpdy|)). A zero footprint resolves every octave; a non-finite
/// one none.
float noiseOctaves(const Vec3f& dpdx, const Vec3f& dpdy, int maxOctaves);

/// The sum over the octaves i < floor(n) of omega^i noise(1.99^i p) (1.99, not 2, so that the
/// octaves' lattices do not line up), plus the next octave weighted by smoothstep(frac(n), 0.3,
/// 0.7), n = noiseOctaves(dpdx, dpdy, maxOctaves).
float fbm(const Vec3f& p, const Vec3f& dpdx, const Vec3f& dpdy, float omega, int maxOctaves);

/// fbm's sum of |noise|; the partial octave blends from 0.2 (about the average of |noise|) to
/// its |noise|, and every octave the footprint cannot resolve adds its average 0.2 omega^i.
float turbulence(const Vec3f& p, const Vec3f& dpdx, const Vec3f& dpdy, float omega, int maxOctaves);

/// A bound of |fbm| and |turbulence| for these omega and maxOctaves: (kPerlinNoiseBound + 0.2)
/// times the sum of |omega|^i over i = 0..maxOctaves (every octave weighs at most |omega|^i
/// times |noise| or its fill-in 0.2, and the partial octave's weight is shared with turbulence's
/// first fill-in).
float noiseSumBound(float omega, int maxOctaves);

}  // namespace lamina
