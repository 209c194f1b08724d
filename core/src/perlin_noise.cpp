#include "lamina/core/perlin_noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lamina {

namespace {

// Perlin's permutation of 0..255 from the reference implementation of "Improving Noise"
// (Perlin 2002), the table pbrt-v4's noise repeats. Indices wrap modulo 256.
constexpr std::array<std::uint8_t, 256> kPermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180,
};

int permute(int i) {
    return kPermutation[std::size_t(i & 255)];
}

struct Gradient {
    float x, y, z;
};

/// Perlin 2002's twelve gradients, the directions to the midpoints of a cube's edges,
/// (+-1, +-1, 0), (+-1, 0, +-1), (0, +-1, +-1), indexed by the low four bits h of a lattice
/// point's hash: its ramp g . (dx, dy, dz) is u + v with u = dx (h < 8, 12, 13) or dy, v = dy
/// (h < 4, 12, 13) or dz, u negated by bit 0 of h and v by bit 1. Hashes 12..15 repeat four of
/// them; they are those of pbrt-v4's Noise, (1, 1, 0), (-1, 1, 0), (0, 1, -1), (0, -1, -1), so
/// that lamina's noise is the one pbrt-v4's procedural media and textures read (Perlin's
/// reference takes (1, 1, 0), (0, -1, 1), (-1, 1, 0), (0, -1, -1) there). A table, not the
/// branches on h: the hash is random, so the branches were mispredicted about half the time
/// (the noise is most of a procedural cloud's cost); the products with +-1 and 0 are exact, so
/// the sums are those of the branches.
constexpr std::array<Gradient, 16> kGradients = [] {
    std::array<Gradient, 16> g{};
    for (int h = 0; h < 16; ++h) {
        const bool uIsX = h < 8 || h == 12 || h == 13, vIsY = h < 4 || h == 12 || h == 13;
        const float u = h & 1 ? -1.0f : 1.0f, v = h & 2 ? -1.0f : 1.0f;
        g[std::size_t(h)] = {uIsX ? u : 0.0f, (uIsX ? 0.0f : u) + (vIsY ? v : 0.0f),
                             vIsY ? 0.0f : v};
    }
    return g;
}();

/// The ramp of lattice point (x, y, z) at offset (dx, dy, dz) from it.
float ramp(int x, int y, int z, float dx, float dy, float dz) {
    const Gradient& g = kGradients[std::size_t(permute(permute(permute(x) + y) + z) & 15)];
    return g.x * dx + g.y * dy + g.z * dz;
}

/// Perlin 2002's fade 6t^5 - 15t^4 + 10t^3: 0 and 1 at the ends with zero first and second
/// derivatives there.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

/// (1 - t) a + t b, clamped to [min(a, b), max(a, b)] so that rounding cannot leave the two.
float blend(float t, float a, float b) {
    return std::clamp((1.0f - t) * a + t * b, std::min(a, b), std::max(a, b));
}

}  // namespace

float perlinNoise(const Vec3f& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0.0f;
    constexpr float kWrap = float(1 << 30);
    // (fmod leaves |c| < kWrap as it is: skipped there, as it costs as much as the rest.)
    const auto wrap = [](float c) { return std::abs(c) < kWrap ? c : std::fmod(c, kWrap); };
    const float x = wrap(p.x), y = wrap(p.y), z = wrap(p.z);
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const float dx = x - fx, dy = y - fy, dz = z - fz;
    // The lattice cell modulo 256 (two's complement: & 255 is the floor modulo for negatives).
    const int ix = int(fx) & 255, iy = int(fy) & 255, iz = int(fz) & 255;
    const float r000 = ramp(ix, iy, iz, dx, dy, dz);
    const float r100 = ramp(ix + 1, iy, iz, dx - 1.0f, dy, dz);
    const float r010 = ramp(ix, iy + 1, iz, dx, dy - 1.0f, dz);
    const float r110 = ramp(ix + 1, iy + 1, iz, dx - 1.0f, dy - 1.0f, dz);
    const float r001 = ramp(ix, iy, iz + 1, dx, dy, dz - 1.0f);
    const float r101 = ramp(ix + 1, iy, iz + 1, dx - 1.0f, dy, dz - 1.0f);
    const float r011 = ramp(ix, iy + 1, iz + 1, dx, dy - 1.0f, dz - 1.0f);
    const float r111 = ramp(ix + 1, iy + 1, iz + 1, dx - 1.0f, dy - 1.0f, dz - 1.0f);
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    const float y0 = blend(wy, blend(wx, r000, r100), blend(wx, r010, r110));
    const float y1 = blend(wy, blend(wx, r001, r101), blend(wx, r011, r111));
    return blend(wz, y0, y1);
}

Vec3f perlinNoiseDifferences(const Vec3f& p) {
    constexpr float kStep = 0.01f;
    const float n = perlinNoise(p);
    return Vec3f(perlinNoise(p + Vec3f(kStep, 0.0f, 0.0f)) - n,
                 perlinNoise(p + Vec3f(0.0f, kStep, 0.0f)) - n,
                 perlinNoise(p + Vec3f(0.0f, 0.0f, kStep)) - n) /
           kStep;
}

}  // namespace lamina
