#include "lamina/scene/texture.h"

#include <algorithm>
#include <cmath>

#include "lamina/image/image_input.h"

namespace lamina::render {

namespace {

TextureMapping2D uvMapping(const Vec2<float>& scale, const Vec2<float>& offset) {
    TextureMapping2D m;
    m.scale = scale;
    m.offset = offset;
    return m;
}

}  // namespace

ImageTexture::ImageTexture(const std::filesystem::path& file, const Vec2<float>& scale, bool srgb,
                           bool invert, const Vec2<float>& offset)
    : ImageTexture(file, uvMapping(scale, offset), srgb, invert) {}

ImageTexture::ImageTexture(const std::filesystem::path& file, const TextureMapping2D& mapping,
                           bool srgb, bool invert)
    : mapping_(mapping), invert_(invert) {
    InputImage image = readInputImage(file, "texture");
    width_ = image.width;
    height_ = image.height;
    const int channels = image.channels;
    const std::vector<float>& data = image.samples;
    const bool decode = srgb && image.integerFormat;
    decodedSrgb_ = decode;
    pixels_.resize(std::size_t(width_) * height_);
    for (std::size_t i = 0; i < pixels_.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            float v = data[i * std::size_t(channels) + std::size_t(std::min(c, channels - 1))];
            // The sRGB transfer function (IEC 61966-2-1), inverted.
            if (decode) v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            pixels_[i][c] = v;
        }
}

Rgb<float> ImageTexture::texel(int x, int y) const {
    x = ((x % width_) + width_) % width_;
    y = ((y % height_) + height_) % height_;
    return pixels_[std::size_t(y) * width_ + x];
}

Rgb<float> ImageTexture::evaluate(const TexturePoint& at) const {
    // t = 0 at the bottom row of the image; bilinear between texel centres, repeating (also
    // towards negative coordinates: a mirrored mapping reads the image backwards).
    const Vec2<float> st = mapping_.map(at);
    float x = st.x * float(width_) - 0.5f;
    float y = (1.0f - st.y) * float(height_) - 0.5f;
    constexpr float kFar = float(1 << 24);
    if (!(std::abs(x) < kFar && std::abs(y) < kFar)) {
        if (!std::isfinite(x) || !std::isfinite(y)) return Rgb<float>(0.0f);
        // Far from the origin (a projected mapping of distant points) the texel index leaves
        // int: the image repeats, so move there by whole images (exact in float out there).
        if (std::abs(x) >= kFar) x = std::fmod(x, float(width_));
        if (std::abs(y) >= kFar) y = std::fmod(y, float(height_));
    }
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    const Rgb<float> value =
        texel(x0, y0) * ((1 - fx) * (1 - fy)) + texel(x0 + 1, y0) * (fx * (1 - fy)) +
        texel(x0, y0 + 1) * ((1 - fx) * fy) + texel(x0 + 1, y0 + 1) * (fx * fy);
    if (!invert_) return value;
    // After the lookup, as pbrt-v4 inverts its filtered value.
    Rgb<float> inverted;
    for (int c = 0; c < 3; ++c)
        inverted[c] = std::max(0.0f, 1.0f - value[c]);
    return inverted;
}

}  // namespace lamina::render
