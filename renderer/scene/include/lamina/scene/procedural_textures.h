// pbrt-v4's procedural textures made of Perlin noise (Pharr, Jakob and Humphreys, "Physically
// Based Rendering", 4th ed., section 10.6; the noise and its octave sums are lamina's own,
// perlin_noise.h and noise_sums.h, which are pbrt-v4's): the solid textures fbm, wrinkled, windy
// and marble, looked up at the point in the texture's space (the `point` mapping,
// texture_mapping.h), and the 2D polka dots. pbrt-v4 sums only the octaves a pixel's footprint
// resolves; lamina has no footprints and sums every octave, pbrt-v4's value as the footprint
// shrinks (noise_sums.h with a zero footprint).
#pragma once

#include <memory>

#include "lamina/scene/texture.h"

namespace lamina::render {

/// The most octaves a noise sum may take: 1.99^i stays far inside float, and a lookup stays
/// cheap whatever a scene file asks.
inline constexpr int kMaxNoiseOctaves = 30;

/// What the two noise-sum textures share: their texture space, octaves and omega (roughness).
class NoiseSumTexture : public Texture {
  public:
    NoiseSumTexture(const TextureSpace& space, int octaves, float roughness)
        : space_(space), octaves_(octaves), omega_(roughness) {}

  protected:
    TextureSpace space_;
    int octaves_;
    float omega_;
};

/// pbrt-v4's FBmTexture: fbm(q, omega = roughness, octaves), q the point in texture space.
class FbmTexture final : public NoiseSumTexture {
  public:
    using NoiseSumTexture::NoiseSumTexture;
    Rgb<float> evaluate(const TexturePoint& at) const override;
};

/// pbrt-v4's WrinkledTexture: turbulence(q, omega = roughness, octaves).
class WrinkledTexture final : public NoiseSumTexture {
  public:
    using NoiseSumTexture::NoiseSumTexture;
    Rgb<float> evaluate(const TexturePoint& at) const override;
};

/// pbrt-v4's WindyTexture: |fbm(q / 10, 1/2, 3)| fbm(q, 1/2, 6), waves whose height a slower
/// noise (the wind's strength) modulates.
class WindyTexture final : public Texture {
  public:
    explicit WindyTexture(const TextureSpace& space) : space_(space) {}
    Rgb<float> evaluate(const TexturePoint& at) const override;

  private:
    TextureSpace space_;
};

/// pbrt-v4's MarbleTexture: with q scaled by `scale`, m = q.y + variation fbm(q, roughness,
/// octaves) and t = 1/2 + sin(m) / 2, the colour 1.5 B(t) of pbrt-v4's marble spline B (a
/// chain of cubic Bezier segments through its nine grey and blue-grey control colours).
class MarbleTexture final : public Texture {
  public:
    MarbleTexture(const TextureSpace& space, int octaves, float roughness, float scale,
                  float variation)
        : space_(space),
          octaves_(octaves),
          omega_(roughness),
          scale_(scale),
          variation_(variation) {}
    Rgb<float> evaluate(const TexturePoint& at) const override;

  private:
    TextureSpace space_;
    int octaves_;
    float omega_, scale_, variation_;
};

/// pbrt-v4's 3D checkerboard (`dimension` 3): `a` where floor(q.x) + floor(q.y) + floor(q.z) is
/// even, `b` where it is odd, q the point in the texture's space (unfiltered).
class SolidCheckerboardTexture final : public Texture {
  public:
    SolidCheckerboardTexture(const Rgb<float>& a, const Rgb<float>& b, const TextureSpace& space)
        : a_(a), b_(b), space_(space) {}
    Rgb<float> evaluate(const TexturePoint& at) const override;

  private:
    Rgb<float> a_, b_;
    TextureSpace space_;
};

/// pbrt-v4's DotsTexture: `inside` within a dot, `outside` elsewhere. Each unit cell around
/// integer (s, t) holds a dot where noise(s + 1/2, t + 1/2) > 0, of radius 0.35, its centre
/// moved by up to 0.15 along each axis by two more noise values.
class DotsTexture final : public Texture {
  public:
    DotsTexture(const TextureMapping2D& mapping, std::shared_ptr<const Texture> inside,
                std::shared_ptr<const Texture> outside)
        : mapping_(mapping), inside_(std::move(inside)), outside_(std::move(outside)) {}
    Rgb<float> evaluate(const TexturePoint& at) const override;
    /// Whether (s, t) lies inside a dot.
    static bool insideDot(const Vec2<float>& st);

  private:
    TextureMapping2D mapping_;
    std::shared_ptr<const Texture> inside_, outside_;
};

}  // namespace lamina::render
