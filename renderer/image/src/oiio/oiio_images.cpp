// lamina's OpenImageIO module: every use of OpenImageIO in lamina, behind the table of
// oiio_images_api.h. Built as a shared library that lamina_render loads on first use.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>

#include "lamina/image/oiio_images_api.h"
#include "stderr_capture.h"

namespace lamina::render::oiio_images {

struct Reader {
    // Declared first, so that it outlives the input: libpng may print while the file closes.
    StderrCapture quiet;  // libpng writes its warnings and errors to stderr
    std::unique_ptr<OIIO::ImageInput> in;
};

namespace {

bool canWrite(const std::string& path) {
    return OIIO::ImageOutput::create(path) != nullptr;
}

void addMetadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata) {
    for (const auto& [k, v] : metadata.strings)
        spec.attribute("lamina:" + k, v);
    for (const auto& [k, v] : metadata.floats)
        spec.attribute("lamina:" + k, v);
    for (const auto& [k, v] : metadata.ints)
        spec.attribute("lamina:" + k, v);
    for (const auto& [k, v] : metadata.matrices)
        spec.attribute("lamina:" + k, OIIO::TypeMatrix44, v.data());
}

bool write(const std::string& formatPath, const std::string& file, const ImageToWrite& image,
           std::string& error) {
    const StderrCapture quiet;  // libpng writes its warnings to stderr
    auto out = OIIO::ImageOutput::create(formatPath);
    if (!out) {
        error = "cannot write this image format";
        return false;
    }
    OIIO::ImageSpec spec(image.width, image.height, int(image.channels.size()),
                         image.eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.x = image.x;
    spec.y = image.y;
    spec.full_x = spec.full_y = 0;
    spec.full_width = image.fullWidth;
    spec.full_height = image.fullHeight;
    spec.channelnames = image.channels;
    if (image.zip) spec.attribute("compression", "zip");
    addMetadata(spec, image.metadata);
    for (const auto& [k, v] : image.attributes)
        spec.attribute(k, v);
    if (image.chromaticities)
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8),
                       image.chromaticities->data());
    if (!out->open(file, spec)) {
        error = "cannot write: " + out->geterror();
        return false;
    }
    const bool ok = out->write_image(OIIO::TypeDesc::FLOAT, image.samples);
    const bool closed = out->close();
    if (!ok || !closed) {
        error = "write failed: " + out->geterror();
        return false;
    }
    return true;
}

void readHeader(const OIIO::ImageSpec& spec, ImageHeader& header) {
    header.x = spec.x;
    header.y = spec.y;
    header.width = spec.width;
    header.height = spec.height;
    header.fullWidth = spec.full_width;
    header.fullHeight = spec.full_height;
    for (int c = 0; c < spec.nchannels; ++c)
        header.channels.emplace_back(spec.channel_name(c));
    header.eightOrSixteenBit =
        spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
    header.floatingPoint = spec.format.is_floating_point();
    header.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    for (const auto& p : spec.extra_attribs) {
        const std::string name = p.name().string();
        header.attributes[name] = p.get_string();
        if (name.rfind("lamina:", 0) != 0) continue;
        const std::string key = name.substr(7);
        ImageMetadata& meta = header.laminaMetadata;
        if (p.type() == OIIO::TypeDesc::INT)
            meta.ints[key] = p.get_int();
        else if (p.type() == OIIO::TypeDesc::FLOAT)
            meta.floats[key] = p.get_float();
        else if (p.type() == OIIO::TypeMatrix44) {
            std::array<float, 16> m{};
            const float* v = static_cast<const float*>(p.data());
            std::copy(v, v + 16, m.begin());
            meta.matrices[key] = m;
        } else
            meta.strings[key] = p.get_string();
    }
}

Reader* open(const std::string& path, ImageHeader& header, Failure& failure) {
    auto reader = std::make_unique<Reader>();
    reader->in = OIIO::ImageInput::open(path);
    if (!reader->in) {
        failure = {OIIO::geterror(), reader->quiet.text()};
        return nullptr;
    }
    readHeader(reader->in->spec(), header);
    return reader.release();
}

bool read(Reader* reader, int channels, float* samples, Failure& failure) {
    if (reader->in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, samples)) return true;
    failure = {reader->in->geterror(), reader->quiet.text()};
    return false;
}

void close(Reader* reader) {
    if (reader->in) reader->in->close();
    delete reader;
}

const Functions kFunctions = {kAbiVersion, canWrite, write, open, read, close};

}  // namespace

}  // namespace lamina::render::oiio_images

extern "C" const lamina::render::oiio_images::Functions* lamina_oiio_images() {
    return &lamina::render::oiio_images::kFunctions;
}
