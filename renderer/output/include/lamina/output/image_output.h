// Writing a render's film: OpenEXR, float RGB with metadata and optional AOV layers that
// Blender and tev read (Albedo.R/G/B, N.X/Y/Z, Z, Variance.Y), and a PNG preview (sRGB, with
// exposure). The files themselves are lamina_image's (image_io.h).
#pragma once

#include <filesystem>

#include "lamina/image/image_io.h"
#include "lamina/render/film.h"

namespace lamina::render {

/// A cropped film is written as its window of the whole image (the EXR data window).
/// `variance` adds Variance.R/G/B and Variance.Y (merged shards).
void writeExr(const std::filesystem::path& path, const Film& film, bool aovs,
              const ImageMetadata& metadata, bool variance = false);
void writePngPreview(const std::filesystem::path& path, const Film& film, double exposure);

}  // namespace lamina::render
