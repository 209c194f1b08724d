#include "lamina/image/image_input.h"

#include <algorithm>
#include <cmath>

#include "lamina/image/image_files.h"
#include "lamina/core/error.h"
#include "lamina/core/input_file.h"

namespace lamina::render {

InputImage readInputImage(const std::filesystem::path& file, const std::string& what) {
    checkInputFile(file, kMaxImageFileBytes);
    Failure failure;
    // `library`: libpng's reason, if it gave one (on stderr, captured by the module).
    auto fail = [&](const std::string& why, const std::string& library) {
        throw InputError(file.string() + ": cannot read the " + what + ": " + why +
                         (library.empty() ? "" : " (" + library + ")"));
    };
    const auto in = openImageFile(file, failure);
    if (!in) fail(failure.message, failure.library);
    const ImageHeader& header = in->header();
    const int nchannels = int(header.channels.size());
    // A small header can claim any resolution: refuse before allocating for it.
    if (header.width <= 0 || header.height <= 0 || nchannels <= 0) fail("the image is empty", "");
    const std::uintmax_t pixels = std::uintmax_t(header.width) * std::uintmax_t(header.height);
    if (pixels > kMaxImagePixels)
        fail(std::to_string(header.width) + " x " + std::to_string(header.height) +
                 " pixels, more than the limit of " + std::to_string(kMaxImagePixels),
             "");
    InputImage image;
    image.width = header.width;
    image.height = header.height;
    image.channels = std::min(nchannels, 3);
    image.integerFormat = header.eightOrSixteenBit;
    image.samples.resize(std::size_t(pixels) * std::size_t(image.channels));
    if (!in->read(image.channels, image.samples.data(), failure))
        fail(failure.message, failure.library);
    // A NaN texel would reach the RGB -> spectrum lookup (an index out of its table) and an
    // infinite one every estimate it touches.
    for (std::size_t i = 0; i < image.samples.size(); ++i)
        if (!std::isfinite(image.samples[i])) {
            const std::size_t pixel = i / std::size_t(image.channels);
            throw InputError(file.string() + ": the " + what +
                             " has a sample that is not finite (" +
                             (std::isnan(image.samples[i]) ? "NaN" : "infinite") + ") at pixel (" +
                             std::to_string(pixel % std::size_t(image.width)) + ", " +
                             std::to_string(pixel / std::size_t(image.width)) + "), channel " +
                             std::to_string(i % std::size_t(image.channels)));
        }
    return image;
}

}  // namespace lamina::render
