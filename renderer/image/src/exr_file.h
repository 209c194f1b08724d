// OpenEXR files through the OpenEXR library itself (scanline, one part): lamina's renders,
// shards and reports, and EXR textures, environment maps and references.
#pragma once

#include <memory>
#include <string>

#include "lamina/image/image_files.h"

namespace lamina::render {

/// Float channels, the data window and display window (full_x = full_y = 0) of `image`, its
/// metadata as "lamina:<key>" attributes of their types, and ZIP compression (what OpenImageIO
/// wrote for lamina before: its default). False and `error` ("cannot write: ...", "write
/// failed: ...") otherwise.
bool writeExrFile(const std::string& file, const ImageToWrite& image, std::string& error);

/// The file begins with OpenEXR's magic number.
bool startsLikeExr(const std::string& file);

/// nullptr and `failure` if the file is not a readable EXR.
std::unique_ptr<ImageFileReader> openExrFile(const std::string& file, Failure& failure);

}  // namespace lamina::render
