#include "lamina/render/image_input.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/render/stderr_capture.h"

namespace lamina::render {

InputImage readInputImage(const std::filesystem::path& file, const std::string& what) {
    checkInputFile(file, kMaxImageFileBytes);
    const StderrCapture quiet;  // libpng writes its warnings and errors to stderr
    auto fail = [&](const std::string& why) {
        const std::string library = quiet.text();  // libpng's reason, if it gave one
        throw InputError(file.string() + ": cannot read the " + what + ": " + why +
                         (library.empty() ? "" : " (" + library + ")"));
    };
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) fail(OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    // A small header can claim any resolution: refuse before allocating for it.
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) fail("the image is empty");
    const std::uintmax_t pixels = std::uintmax_t(spec.width) * std::uintmax_t(spec.height);
    if (pixels > kMaxImagePixels)
        fail(std::to_string(spec.width) + " x " + std::to_string(spec.height) +
             " pixels, more than the limit of " + std::to_string(kMaxImagePixels));
    InputImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(spec.nchannels, 3);
    image.integerFormat =
        spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
    image.samples.resize(std::size_t(pixels) * std::size_t(image.channels));
    if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.samples.data()))
        fail(in->geterror());
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
