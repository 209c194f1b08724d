// Reading an input image (a texture, an environment map: EXR through OpenEXR, anything else through
// lamina's OpenImageIO module, loaded on first use) behind the checks every input file gets: a
// regular file of sane size (input_file.h), a sane number of pixels before anything is allocated,
// and every sample finite. Errors name the file and the first bad pixel.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lamina::render {

struct InputImage {
    int width = 0, height = 0;
    int channels = 0;            ///< 1 to 3: the first three channels of the file
    bool integerFormat = false;  ///< stored as 8- or 16-bit integers (sRGB-encoded, usually)
    std::vector<float> samples;  ///< width * height * channels, top row first
};

/// `what` names the image's role in messages ("texture", "environment map").
InputImage readInputImage(const std::filesystem::path& file, const std::string& what);

}  // namespace lamina::render
