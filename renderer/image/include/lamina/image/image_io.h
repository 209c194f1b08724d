// Images as files: float EXR files of named channels (through the OpenEXR library) with lamina's
// metadata, 8-bit display images (PNG through lamina's own writer), and any image read back as
// float (EXR through OpenEXR; PNG, JPEG, HDR, TIFF, ... through lamina's OpenImageIO module,
// loaded only for them). Files are written under a temporary name in the same directory and
// renamed, so an interrupted write never leaves a broken file behind.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "lamina/image/image_metadata.h"
#include "lamina/image/pixel_bounds.h"

namespace lamina::render {

/// Checks that the image `path` can be written before a long render starts (checkOutputFile:
/// a writable directory, not a directory, not one of `inputs`, a name that fits; and a format
/// known from the extension: .exr, .png, or one OpenImageIO writes, which loads the module);
/// InputError otherwise.
void checkOutputPath(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs = {});

/// An EXR of named float channels (interleaved `data`, width x height x channels.size()).
void writeFloatExr(const std::filesystem::path& path, int width, int height,
                   const std::vector<std::string>& channels, const std::vector<float>& data,
                   const ImageMetadata& metadata = {});
/// The same for the pixels `window` of a fullWidth x fullHeight image (the EXR data window).
void writeFloatExr(const std::filesystem::path& path, const PixelBounds& window, int fullWidth,
                   int fullHeight, const std::vector<std::string>& channels,
                   const std::vector<float>& data, const ImageMetadata& metadata = {});
/// An 8-bit image (PNG, ...) of display-ready RGB values in [0, 1] (no transfer function).
void writeRgb8(const std::filesystem::path& path, int width, int height,
               const std::vector<float>& rgb);
/// A float RGB image read back (tests, comparisons).
struct RgbImage {
    int width = 0, height = 0;
    std::vector<float> pixels;  ///< linear RGB interleaved
    std::map<std::string, std::string> metadata;
    /// The file was sRGB-encoded (8- or 16-bit PNG, JPEG, ...): its pixels are decoded to
    /// linear, but it was tone-mapped and clipped for display, so it is not comparable with a
    /// linear render.
    bool displayReferred = false;
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * 3 + c]; }
};
/// Channels R, G and B by name (an InputError names the channels found otherwise); an
/// sRGB-encoded file is decoded to linear and marked displayReferred. EXR through OpenEXR,
/// anything else through lamina's OpenImageIO module.
RgbImage readRgbImage(const std::filesystem::path& path);
/// The same for a reference of a linear render: refuses a display-referred image.
RgbImage readLinearRgbImage(const std::filesystem::path& path);

/// Every channel of an image as stored (no decoding), with its data window and metadata.
struct FloatImage {
    int x = 0, y = 0, width = 0, height = 0;  ///< the data window
    int fullWidth = 0, fullHeight = 0;        ///< the display window, from (0, 0)
    /// In the order OpenImageIO gives them: R, G, B, A of each layer first, layers by name.
    std::vector<std::string> channels;
    std::vector<float> samples;  ///< width * height * channels.size(), interleaved, top row first
    ImageMetadata metadata;      ///< the "lamina:<key>" attributes, typed
    std::map<std::string, std::string> attributes;  ///< every attribute, as text
    /// The index of channel `name`, -1 if there is none.
    int channel(const std::string& name) const;
    float at(int px, int py, int c) const {
        return samples[(std::size_t(py) * width + px) * channels.size() + std::size_t(c)];
    }
};
/// InputError naming the file if it cannot be read or has more than kMaxImagePixels pixels.
FloatImage readFloatImage(const std::filesystem::path& path);

}  // namespace lamina::render
