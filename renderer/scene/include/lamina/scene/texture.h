// Textures for material parameters (colours and roughness), looked up at a surface point
// (texture_mapping.h: its uv, or its position for the mappings that project it): a
// checkerboard and images (EXR through OpenEXR, other formats through lamina's OpenImageIO module,
// image_input.h; bilinear, repeating; 8-bit images are decoded from sRGB unless declared linear;
// optionally inverted), and the operations on textures that pbrt-v4 scenes use: a texture times a
// number, a mix of two (by an amount, or by the normal's alignment with a direction), and a
// texture to a power (the remapping of a looked-up roughness). Only the
// renderer knows textures: the BSDF library receives the looked-up values (material_textures.h
// reads them from a scene file and looks them up; render_mode.h rebuilds a textured material per
// hit). The procedural textures of pbrt-v4 made of noise are in procedural_textures.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"
#include "lamina/scene/texture_mapping.h"

namespace lamina::render {

/// The `type` of a texture in a scene file.
enum class TextureKind {
    Checkerboard,
    Image,
    Scale,
    Mix,
    Power,
    Fbm,
    Wrinkled,
    Windy,
    Marble,
    Dots,
    DirectionMix
};
inline constexpr NameTable kTextureKindNames{std::array{
    NameEntry{TextureKind::Checkerboard, "checkerboard"}, NameEntry{TextureKind::Image, "image"},
    NameEntry{TextureKind::Scale, "scale"}, NameEntry{TextureKind::Mix, "mix"},
    NameEntry{TextureKind::Power, "power"}, NameEntry{TextureKind::Fbm, "fbm"},
    NameEntry{TextureKind::Wrinkled, "wrinkled"}, NameEntry{TextureKind::Windy, "windy"},
    NameEntry{TextureKind::Marble, "marble"}, NameEntry{TextureKind::Dots, "dots"},
    NameEntry{TextureKind::DirectionMix, "direction_mix"}}};

/// How an image texture's integer texels are decoded: sRGB or linear.
enum class TextureColorSpace { Srgb, Linear };
inline constexpr NameTable kTextureColorSpaceNames{std::array{
    NameEntry{TextureColorSpace::Srgb, "srgb"}, NameEntry{TextureColorSpace::Linear, "linear"}}};

class Texture {
  public:
    virtual ~Texture() = default;
    virtual Rgb<float> evaluate(const TexturePoint& at) const = 0;
};

/// `a` where floor(s) + floor(t) is even, `b` where it is odd ((s, t) from the mapping; pbrt-v4's
/// checkerboard, unfiltered).
class CheckerboardTexture final : public Texture {
  public:
    CheckerboardTexture(const Rgb<float>& a, const Rgb<float>& b, const TextureMapping2D& mapping)
        : a_(a), b_(b), mapping_(mapping) {}
    CheckerboardTexture(const Rgb<float>& a, const Rgb<float>& b, const Vec2<float>& scale)
        : a_(a), b_(b) {
        mapping_.scale = scale;
    }
    Rgb<float> evaluate(const TexturePoint& at) const override {
        const Vec2<float> st = mapping_.map(at);
        const float fs = std::floor(st.x), ft = std::floor(st.y);
        constexpr float kIntRange = float(1 << 30);
        if (std::abs(fs) < kIntRange && std::abs(ft) < kIntRange)
            return ((int(fs) + int(ft)) & 1) ? b_ : a_;
        // Far out (a projected mapping of distant points) or not a number: the parity without
        // an int those coordinates would leave.
        return std::fmod(std::abs(fs), 2.0f) != std::fmod(std::abs(ft), 2.0f) ? b_ : a_;
    }

  private:
    Rgb<float> a_, b_;
    TextureMapping2D mapping_;
};

class ImageTexture final : public Texture {
  public:
    /// `srgb`: decode 8- and 16-bit integer images with the sRGB transfer function.
    /// `invert`: max(0, 1 - value) per channel after decoding (pbrt-v4's imagemap `invert`).
    /// The image is looked up at the mapping's (s, t): by default scale * uv + offset (pbrt-v4's
    /// UVMapping: uscale, vscale, udelta, vdelta; a negative scale mirrors the image).
    ImageTexture(const std::filesystem::path& file, const TextureMapping2D& mapping, bool srgb,
                 bool invert);
    ImageTexture(const std::filesystem::path& file, const Vec2<float>& scale, bool srgb,
                 bool invert, const Vec2<float>& offset = Vec2<float>(0.0f));
    Rgb<float> evaluate(const TexturePoint& at) const override;
    /// Its texels were decoded from sRGB (an integer image not declared linear).
    bool decodedSrgb() const { return decodedSrgb_; }

  private:
    Rgb<float> texel(int x, int y) const;
    int width_ = 0, height_ = 0;
    std::vector<Rgb<float>> pixels_;
    TextureMapping2D mapping_;
    bool invert_;
    bool decodedSrgb_ = false;
};

/// The same colour everywhere: a constant operand of an operation.
class ConstantTexture final : public Texture {
  public:
    explicit ConstantTexture(const Rgb<float>& value) : value_(value) {}
    Rgb<float> evaluate(const TexturePoint&) const override { return value_; }

  private:
    Rgb<float> value_;
};

/// A texture times a number (pbrt-v4's `scale` texture with a constant scale).
class ScaleTexture final : public Texture {
  public:
    ScaleTexture(std::shared_ptr<const Texture> texture, float scale)
        : texture_(std::move(texture)), scale_(scale) {}
    Rgb<float> evaluate(const TexturePoint& at) const override {
        return texture_->evaluate(at) * scale_;
    }

  private:
    std::shared_ptr<const Texture> texture_;
    float scale_;
};

/// Each channel of a texture to a power, after the lookup: max(0, value)^exponent. A roughness
/// map stores what a renderer remaps after looking it up (pbrt-v4's alpha = sqrt(roughness),
/// lamina's roughness = sqrt(alpha)), and the remapping of a bilinear lookup is not the lookup of
/// remapped texels: this texture applies it where the other renderer does.
class PowerTexture final : public Texture {
  public:
    PowerTexture(std::shared_ptr<const Texture> texture, float exponent)
        : texture_(std::move(texture)), exponent_(exponent) {}
    Rgb<float> evaluate(const TexturePoint& at) const override {
        const Rgb<float> v = texture_->evaluate(at);
        Rgb<float> out;
        for (int c = 0; c < 3; ++c)
            out[c] = std::pow(std::max(v[c], 0.0f), exponent_);
        return out;
    }

  private:
    std::shared_ptr<const Texture> texture_;
    float exponent_;
};

/// (1 - t) a + t b, t the first channel of `amount` (pbrt-v4's `mix` texture).
class MixTexture final : public Texture {
  public:
    MixTexture(std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b,
               std::shared_ptr<const Texture> amount)
        : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}
    Rgb<float> evaluate(const TexturePoint& at) const override {
        const float t = amount_->evaluate(at)[0];
        return a_->evaluate(at) * (1 - t) + b_->evaluate(at) * t;
    }

  private:
    std::shared_ptr<const Texture> a_, b_, amount_;
};

/// t a + (1 - t) b with t = |n . direction|, n the surface's geometric normal: `a` where the
/// surface faces along the direction (or against it), `b` where it is seen edge-on from there
/// (pbrt-v4's `directionmix` texture, whose tex1 is `a`).
class DirectionMixTexture final : public Texture {
  public:
    /// `direction` unit.
    DirectionMixTexture(std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b,
                        const Vec3<float>& direction)
        : a_(std::move(a)), b_(std::move(b)), direction_(direction) {}
    Rgb<float> evaluate(const TexturePoint& at) const override {
        const float t = std::min(std::abs(glm::dot(at.n, direction_)), 1.0f);
        return a_->evaluate(at) * t + b_->evaluate(at) * (1 - t);
    }

  private:
    std::shared_ptr<const Texture> a_, b_;
    Vec3<float> direction_;
};

}  // namespace lamina::render
