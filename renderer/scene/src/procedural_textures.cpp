#include "lamina/scene/procedural_textures.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "lamina/core/noise_sums.h"
#include "lamina/core/perlin_noise.h"

namespace lamina::render {

namespace {

/// No footprint: every octave of a sum (noise_sums.h).
const Vec3<float> kNoFootprint(0.0f);

/// The control colours of pbrt-v4's marble spline (its MarbleTexture, textures.cpp): six cubic
/// Bezier segments, segment i through colours i .. i + 3.
constexpr std::array<std::array<float, 3>, 9> kMarbleColours = {{{0.58f, 0.58f, 0.6f},
                                                                 {0.58f, 0.58f, 0.6f},
                                                                 {0.58f, 0.58f, 0.6f},
                                                                 {0.5f, 0.5f, 0.5f},
                                                                 {0.6f, 0.59f, 0.58f},
                                                                 {0.58f, 0.58f, 0.6f},
                                                                 {0.58f, 0.58f, 0.6f},
                                                                 {0.2f, 0.2f, 0.33f},
                                                                 {0.58f, 0.58f, 0.6f}}};

/// The cubic Bezier curve of control values c0..c3 at u: the Bernstein form
/// (1-u)^3 c0 + 3 (1-u)^2 u c1 + 3 (1-u) u^2 c2 + u^3 c3.
float cubicBezier(float c0, float c1, float c2, float c3, float u) {
    const float v = 1.0f - u;
    return v * v * v * c0 + 3.0f * v * v * u * c1 + 3.0f * v * u * u * c2 + u * u * u * c3;
}

}  // namespace

Rgb<float> FbmTexture::evaluate(const TexturePoint& at) const {
    return Rgb<float>(fbm(space_(at.p), kNoFootprint, kNoFootprint, omega_, octaves_));
}

Rgb<float> WrinkledTexture::evaluate(const TexturePoint& at) const {
    return Rgb<float>(turbulence(space_(at.p), kNoFootprint, kNoFootprint, omega_, octaves_));
}

Rgb<float> WindyTexture::evaluate(const TexturePoint& at) const {
    const Vec3<float> q = space_(at.p);
    const float wind = fbm(0.1f * q, kNoFootprint, kNoFootprint, 0.5f, 3);
    const float waves = fbm(q, kNoFootprint, kNoFootprint, 0.5f, 6);
    return Rgb<float>(std::abs(wind) * waves);
}

Rgb<float> MarbleTexture::evaluate(const TexturePoint& at) const {
    const Vec3<float> q = scale_ * space_(at.p);
    const float m = q.y + variation_ * fbm(q, kNoFootprint, kNoFootprint, omega_, octaves_);
    float t = 0.5f + 0.5f * std::sin(m);
    if (!std::isfinite(t)) t = 0.5f;
    constexpr int kSegments = int(kMarbleColours.size()) - 3;
    const int first = std::clamp(int(std::floor(t * kSegments)), 0, kSegments - 1);
    const float u = t * kSegments - float(first);
    Rgb<float> c;
    for (int k = 0; k < 3; ++k)
        c[k] = 1.5f * cubicBezier(kMarbleColours[std::size_t(first)][std::size_t(k)],
                                  kMarbleColours[std::size_t(first + 1)][std::size_t(k)],
                                  kMarbleColours[std::size_t(first + 2)][std::size_t(k)],
                                  kMarbleColours[std::size_t(first + 3)][std::size_t(k)], u);
    return c;
}

Rgb<float> SolidCheckerboardTexture::evaluate(const TexturePoint& at) const {
    const Vec3<float> q = space_(at.p);
    // Each axis's parity as floor(x) - 2 floor(x / 2), 0 or 1: exact for every finite float
    // (beyond 2^24 every float is an even integer), and NaN for NaN (then `b`).
    float odd = 0.0f;
    for (int k = 0; k < 3; ++k) {
        const float f = std::floor(q[k]);
        odd += f - 2.0f * std::floor(0.5f * f);
    }
    return odd == 0.0f || odd == 2.0f ? a_ : b_;
}

bool DotsTexture::insideDot(const Vec2<float>& st) {
    // pbrt-v4's InsidePolkaDot: the cell's noise at z = 1/2 (its Noise(x, y) default).
    const float sCell = std::floor(st.x + 0.5f), tCell = std::floor(st.y + 0.5f);
    if (!(perlinNoise(Vec3<float>(sCell + 0.5f, tCell + 0.5f, 0.5f)) > 0.0f)) return false;
    constexpr float kRadius = 0.35f, kMaxShift = 0.5f - kRadius;
    const float sCentre =
        sCell + kMaxShift * perlinNoise(Vec3<float>(sCell + 1.5f, tCell + 2.8f, 0.5f));
    const float tCentre =
        tCell + kMaxShift * perlinNoise(Vec3<float>(sCell + 4.5f, tCell + 9.8f, 0.5f));
    const float ds = st.x - sCentre, dt = st.y - tCentre;
    return ds * ds + dt * dt < kRadius * kRadius;
}

Rgb<float> DotsTexture::evaluate(const TexturePoint& at) const {
    return insideDot(mapping_.map(at)) ? inside_->evaluate(at) : outside_->evaluate(at);
}

}  // namespace lamina::render
