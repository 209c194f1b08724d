// Image files by format, for the image readers and writers (image_io.cpp, image_input.cpp) and
// the render's files (output/: image_output.cpp, shard_file.cpp): EXR through
// OpenEXR (exr_file.cpp), 8-bit RGB PNG through lamina's own writer (png_file.cpp), anything
// else through lamina's OpenImageIO module (oiio_module.h), loaded only then.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "lamina/image/oiio_images_api.h"
#include "lamina/image/pixel_bounds.h"

namespace lamina::render {

using oiio_images::Failure;
using oiio_images::ImageHeader;
using oiio_images::ImageToWrite;

/// An open image file: its header, then its pixels.
class ImageFileReader {
  public:
    virtual ~ImageFileReader() = default;
    const ImageHeader& header() const { return header_; }
    /// The first `channels` of header().channels of every pixel, interleaved, top row first,
    /// into width * height * channels floats; false and `failure` if the file is broken.
    virtual bool read(int channels, float* samples, Failure& failure) = 0;

  protected:
    ImageHeader header_;
};

/// The file is an EXR (by its extension, as OpenImageIO chose a reader's format).
bool isExrPath(const std::filesystem::path& path);
/// nullptr and `failure` if it cannot be opened; InputError if it needs the OpenImageIO module
/// and the module cannot be loaded.
std::unique_ptr<ImageFileReader> openImageFile(const std::filesystem::path& path, Failure& failure);

/// The format of `path` (its extension) can be written: EXR, PNG or one OpenImageIO knows.
bool canWriteImageFormat(const std::filesystem::path& path);
/// Writes `image` under a temporary name beside `path`, then renames it: InputError naming
/// `path` if anything fails (the temporary is removed).
void writeImageFile(const std::filesystem::path& path, const ImageToWrite& image);

/// A float image of `channels` (interleaved `data`, which must outlive the result), zip
/// compressed, as the whole width x height image.
ImageToWrite floatImage(int width, int height, const std::vector<std::string>& channels,
                        const std::vector<float>& data, const ImageMetadata& metadata);
/// Places the image at `window` of a fullWidth x fullHeight image.
void setDataWindow(ImageToWrite& image, const PixelBounds& window, int fullWidth, int fullHeight);
/// An 8-bit RGB image of display-ready values.
ImageToWrite rgb8Image(int width, int height, const std::vector<float>& rgb);

}  // namespace lamina::render
