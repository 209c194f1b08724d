// The interface between lamina_render and lamina's OpenImageIO module (lamina_oiio_images, a
// shared library loaded on first use by oiio_module.cpp): linking OpenImageIO pulls in some
// 260 shared libraries whose symbol lookups cost every process about 0.3 s before main, so only
// the module links it and only images that OpenEXR and lamina's PNG writer cannot handle
// (reading PNG, JPEG, HDR, TIFF, ...; writing formats other than EXR and PNG) load it.
//
// One extern "C" entry point returns a table of plain function pointers: no vtables or type
// information cross the boundary, and errors come back as text (no exception does). Both sides
// are built together by the same compiler and standard library, so the C++ types are shared.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lamina/image/image_metadata.h"

namespace lamina::render::oiio_images {

/// The pixels (x, y, width, height), the data window, of a fullWidth x fullHeight image.
struct ImageToWrite {
    int x = 0, y = 0, width = 0, height = 0;
    int fullWidth = 0, fullHeight = 0;
    std::vector<std::string> channels;
    bool eightBit = false;  ///< stored as 8-bit integers (samples in [0, 1]), else 32-bit float
    bool zip = false;       ///< the "compression" attribute "zip" (EXR)
    ImageMetadata metadata;
    /// The EXR "chromaticities" attribute: red, green, blue and white x, y.
    std::optional<std::array<float, 8>> chromaticities;
    /// String attributes of other conventions, under their own names (the spectral layout's).
    std::map<std::string, std::string> attributes;
    const float* samples = nullptr;  ///< width * height * channels.size(), interleaved
};

/// What a file says about itself before its pixels are read.
struct ImageHeader {
    int x = 0, y = 0, width = 0, height = 0;        ///< the data window
    int fullWidth = 0, fullHeight = 0;              ///< the display window, from (0, 0)
    std::vector<std::string> channels;              ///< in the order read() delivers them
    bool eightOrSixteenBit = false;                 ///< stored as 8- or 16-bit integers
    bool floatingPoint = true;                      ///< stored as half or float
    std::string colorSpace;                         ///< "oiio:ColorSpace", if the file says
    ImageMetadata laminaMetadata;                   ///< the "lamina:<key>" attributes, typed
    std::map<std::string, std::string> attributes;  ///< every attribute, as text
};

/// Why an image could not be read: the reader's message, and what the library (libpng)
/// printed on stderr meanwhile, if anything.
struct Failure {
    std::string message, library;
};

struct Reader;  // an open file, owned by the module

struct Functions {
    int abiVersion;
    /// OpenImageIO can write the format of `path` (from its extension).
    bool (*canWrite)(const std::string& path);
    /// Writes `image` to `file` in the format of `formatPath`; false with `error` ("cannot
    /// write: ...", "write failed: ...") otherwise.
    bool (*write)(const std::string& formatPath, const std::string& file, const ImageToWrite& image,
                  std::string& error);
    /// Opens `path` and fills `header`; nullptr and `failure` if it cannot.
    Reader* (*open)(const std::string& path, ImageHeader& header, Failure& failure);
    /// Reads the first `channels` channels of every pixel into `samples` (top row first).
    bool (*read)(Reader* reader, int channels, float* samples, Failure& failure);
    void (*close)(Reader* reader);
};

inline constexpr int kAbiVersion = 2;
inline constexpr const char* kEntryPoint = "lamina_oiio_images";

}  // namespace lamina::render::oiio_images

extern "C" const lamina::render::oiio_images::Functions* lamina_oiio_images();
