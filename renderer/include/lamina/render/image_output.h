// Writing renders: OpenEXR (through OpenImageIO), float RGB with metadata and optional AOV
// layers that Blender and tev read (Albedo.R/G/B, N.X/Y/Z, Z, Variance.Y), and a PNG preview
// (sRGB, with exposure). Files are written under a temporary name in the same directory and
// renamed, so an interrupted write never leaves a broken file behind.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "lamina/render/film.h"

namespace lamina::render {

struct ImageMetadata {
    std::map<std::string, std::string> strings;  ///< written as "lamina:<key>"
    std::map<std::string, float> floats;
    std::map<std::string, int> ints;
    std::map<std::string, std::array<float, 16>> matrices;  ///< row-major 4x4 (M44f)
};

/// Checks that the image `path` can be written before a long render starts (checkOutputFile:
/// a writable directory, not a directory, not one of `inputs`, a name that fits; and a format
/// OpenImageIO knows from the extension); InputError otherwise.
void checkOutputPath(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs = {});

/// A cropped film is written as its window of the whole image (the EXR data window).
/// `variance` adds Variance.R/G/B and Variance.Y (merged shards).
void writeExr(const std::filesystem::path& path, const Film& film, bool aovs,
              const ImageMetadata& metadata, bool variance = false);
void writePngPreview(const std::filesystem::path& path, const Film& film, double exposure);

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
/// sRGB-encoded file is decoded to linear and marked displayReferred.
RgbImage readRgbImage(const std::filesystem::path& path);
/// The same for a reference of a linear render: refuses a display-referred image.
RgbImage readLinearRgbImage(const std::filesystem::path& path);

}  // namespace lamina::render
