#include "lamina/scene/texture.h"

#include <algorithm>
#include <cmath>

#include "lamina/image/image_input.h"

namespace lamina::render {

ImageTexture::ImageTexture(const std::filesystem::path& file, const Vec2<float>& scale, bool srgb,
                           bool invert, const Vec2<float>& offset)
    : scale_(scale), invert_(invert), offset_(offset) {
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

Rgb<float> ImageTexture::evaluate(const Vec2<float>& uv) const {
    // v = 0 at the bottom row of the image; bilinear between texel centres, repeating.
    // An offset of 0 adds exactly nothing: without one the lookup is what it was.
    const float x = (uv.x * scale_.x + offset_.x) * float(width_) - 0.5f;
    const float y = (1.0f - (uv.y * scale_.y + offset_.y)) * float(height_) - 0.5f;
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
