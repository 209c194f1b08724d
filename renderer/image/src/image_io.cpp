#include "lamina/image/image_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/core/output_files.h"
#include "lamina/image/image_files.h"

namespace lamina::render {

void checkOutputPath(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs) {
    checkOutputFile(path, inputs);
    if (!canWriteImageFormat(path))
        throw InputError(path.string() + ": unknown image format \"" + path.extension().string() +
                         "\" (use .exr)");
}

void writeFloatExr(const std::filesystem::path& path, int width, int height,
                   const std::vector<std::string>& channels, const std::vector<float>& data,
                   const ImageMetadata& metadata) {
    writeImageFile(path, floatImage(width, height, channels, data, metadata));
}

void writeFloatExr(const std::filesystem::path& path, const PixelBounds& window, int fullWidth,
                   int fullHeight, const std::vector<std::string>& channels,
                   const std::vector<float>& data, const ImageMetadata& metadata) {
    ImageToWrite image = floatImage(window.width(), window.height(), channels, data, metadata);
    setDataWindow(image, window, fullWidth, fullHeight);
    writeImageFile(path, image);
}

void writeRgb8(const std::filesystem::path& path, int width, int height,
               const std::vector<float>& rgb) {
    writeImageFile(path, rgb8Image(width, height, rgb));
}

namespace {

/// The index of channel `name`, or -1.
int channelIndex(const ImageHeader& header, const std::string& name) {
    for (std::size_t c = 0; c < header.channels.size(); ++c)
        if (header.channels[c] == name) return int(c);
    return -1;
}

/// An 8- or 16-bit file is sRGB-encoded unless it says otherwise (PNG, JPEG); a float file is
/// linear unless it says it is sRGB.
bool isSrgbEncoded(const ImageHeader& header) {
    std::string cs = header.colorSpace;
    std::transform(cs.begin(), cs.end(), cs.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (cs.find("srgb") != std::string::npos && cs.find("lin") == std::string::npos) return true;
    const bool integer = !header.floatingPoint;
    return integer && cs.empty();
}

double srgbToLinear(double e) {
    // The inverse of the sRGB transfer function (IEC 61966-2-1).
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

}  // namespace

namespace {

/// The file open, its pixel count within kMaxImagePixels.
std::unique_ptr<ImageFileReader> openWithinLimits(const std::filesystem::path& path) {
    checkInputFile(path, kMaxImageFileBytes);
    Failure failure;
    auto in = openImageFile(path, failure);
    if (!in) throw InputError(path.string() + ": cannot read image: " + failure.message);
    const ImageHeader& header = in->header();
    // A small header can claim any resolution: refuse before allocating for it.
    if (std::uintmax_t(std::max(header.width, 0)) * std::uintmax_t(std::max(header.height, 0)) >
        kMaxImagePixels)
        throw InputError(path.string() + ": " + std::to_string(header.width) + " x " +
                         std::to_string(header.height) + " pixels, more than the limit of " +
                         std::to_string(kMaxImagePixels));
    return in;
}

/// Every channel of every pixel, interleaved.
std::vector<float> readAllChannels(ImageFileReader& in, const std::filesystem::path& path) {
    const ImageHeader& header = in.header();
    std::vector<float> all(std::size_t(header.width) * std::size_t(header.height) *
                           header.channels.size());
    Failure failure;
    if (!in.read(int(header.channels.size()), all.data(), failure))
        throw InputError(path.string() + ": cannot read image: " + failure.message +
                         (failure.library.empty() ? "" : " (" + failure.library + ")"));
    return all;
}

}  // namespace

RgbImage readRgbImage(const std::filesystem::path& path) {
    const auto in = openWithinLimits(path);
    const ImageHeader& header = in->header();
    // By name, not by position: an EXR's channels are stored sorted (A before B, G, R, and
    // AOV layers such as Albedo.R before R).
    const int channels[3] = {channelIndex(header, "R"), channelIndex(header, "G"),
                             channelIndex(header, "B")};
    if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
        std::string names;
        for (std::size_t c = 0; c < header.channels.size(); ++c)
            names += std::string(c ? ", " : "") + header.channels[c];
        throw InputError(path.string() + ": expected channels R, G and B, found " +
                         (names.empty() ? std::string("none") : names));
    }
    RgbImage img;
    img.width = header.width;
    img.height = header.height;
    img.displayReferred = isSrgbEncoded(header);
    const std::size_t nc = header.channels.size(), n = std::size_t(header.width) * header.height;
    const std::vector<float> all = readAllChannels(*in, path);
    img.pixels.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = all[i * nc + std::size_t(channels[c])];
            img.pixels[i * 3 + std::size_t(c)] =
                img.displayReferred ? float(srgbToLinear(double(v))) : v;
        }
    img.metadata = header.attributes;
    return img;
}

FloatImage readFloatImage(const std::filesystem::path& path) {
    const auto in = openWithinLimits(path);
    const ImageHeader& header = in->header();
    FloatImage img;
    img.x = header.x;
    img.y = header.y;
    img.width = header.width;
    img.height = header.height;
    img.fullWidth = header.fullWidth;
    img.fullHeight = header.fullHeight;
    img.channels = header.channels;
    img.samples = readAllChannels(*in, path);
    img.metadata = header.laminaMetadata;
    img.attributes = header.attributes;
    return img;
}

int FloatImage::channel(const std::string& name) const {
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c] == name) return int(c);
    return -1;
}

RgbImage readLinearRgbImage(const std::filesystem::path& path) {
    RgbImage img = readRgbImage(path);
    if (img.displayReferred)
        throw InputError(path.string() +
                         ": an sRGB-encoded display image (tone-mapped and clipped to [0, 1]) "
                         "cannot be a reference for a linear render: use the EXR");
    return img;
}

}  // namespace lamina::render
