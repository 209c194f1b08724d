#include "lamina/render/image_output.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/render/stderr_capture.h"
#include "lamina/spectral/color_space.h"

namespace lamina::render {

namespace {

void writeAtomically(const std::filesystem::path& path, const OIIO::ImageSpec& spec,
                     const std::vector<float>& data) {
    const StderrCapture quiet;  // libpng writes its warnings to stderr
    TemporaryFile tmp(path);    // removed if anything below fails
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw InputError(path.string() + ": cannot write this image format");
    if (!out->open(tmp.path().string(), spec))
        throw InputError(path.string() + ": cannot write: " + out->geterror());
    const bool ok = out->write_image(OIIO::TypeDesc::FLOAT, data.data());
    const bool closed = out->close();
    if (!ok || !closed) throw InputError(path.string() + ": write failed: " + out->geterror());
    tmp.commit();
}

void addMetadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata) {
    for (const auto& [k, v] : metadata.strings)
        spec.attribute("lamina:" + k, v);
    for (const auto& [k, v] : metadata.floats)
        spec.attribute("lamina:" + k, v);
    for (const auto& [k, v] : metadata.ints)
        spec.attribute("lamina:" + k, v);
}

}  // namespace

void checkOutputPath(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs) {
    checkOutputFile(path, inputs);
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw InputError(path.string() + ": unknown image format \"" + path.extension().string() +
                         "\" (use .exr)");
}

void writeExr(const std::filesystem::path& path, const Film& film, bool aovs,
              const ImageMetadata& metadata) {
    const int w = film.width(), h = film.height();
    std::vector<std::string> channels = {"R", "G", "B"};
    if (aovs)
        channels.insert(channels.end(), {"Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z",
                                         "Z", "Variance.Y"});
    const std::size_t nc = channels.size();
    OIIO::ImageSpec spec(w, h, int(nc), OIIO::TypeDesc::FLOAT);
    spec.channelnames = channels;
    spec.attribute("compression", "zip");
    addMetadata(spec, metadata);
    // The primaries and white of lamina's linear Rec.709 (the EXR "chromaticities" attribute).
    const RgbColorSpace& cs = RgbColorSpace::rec709();
    const Vec3d white = cs.whiteXyz();
    const double sum = white.x + white.y + white.z;
    const float chroma[8] = {float(cs.red().x),    float(cs.red().y),   float(cs.green().x),
                             float(cs.green().y),  float(cs.blue().x),  float(cs.blue().y),
                             float(white.x / sum), float(white.y / sum)};
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chroma);

    std::vector<float> data(std::size_t(w) * h * nc);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &data[(std::size_t(y) * w + x) * nc];
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = float(v[c]);
            if (!aovs) continue;
            const PixelAovs a = film.aovs(x, y);
            for (int c = 0; c < 3; ++c) {
                p[3 + c] = float(a.albedo[c]);
                p[6 + c] = float(a.normal[c]);
            }
            p[9] = float(a.depth);
            p[10] = float(film.varianceOfMean(x, y));
        }
    writeAtomically(path, spec, data);
}

void writeFloatExr(const std::filesystem::path& path, int width, int height,
                   const std::vector<std::string>& channels, const std::vector<float>& data,
                   const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(width, height, int(channels.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = channels;
    addMetadata(spec, metadata);
    writeAtomically(path, spec, data);
}

void writeRgb8(const std::filesystem::path& path, int width, int height,
               const std::vector<float>& rgb) {
    writeAtomically(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), rgb);
}

void writeSignedHeatMap(const std::filesystem::path& path, int width, int height,
                        const std::vector<float>& values, double limit) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    std::vector<float> data(std::size_t(width) * height * 3, 0.0f);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double t = std::clamp(double(values[i]) / limit, -1.0, 1.0);
        data[3 * i + (t > 0 ? 0 : 2)] = float(std::sqrt(std::abs(t)));
    }
    writeAtomically(path, spec, data);
}

void writePngPreview(const std::filesystem::path& path, const Film& film, double exposure) {
    const int w = film.width(), h = film.height();
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    std::vector<float> data(std::size_t(w) * h * 3);
    const double scale = std::exp2(exposure);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                // The sRGB transfer function (IEC 61966-2-1).
                const double l = std::clamp(v[c] * scale, 0.0, 1.0);
                const double e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
                data[(std::size_t(y) * w + x) * 3 + std::size_t(c)] = float(e);
            }
        }
    writeAtomically(path, spec, data);
}

RgbImage readRgbImage(const std::filesystem::path& path) {
    const StderrCapture quiet;  // libpng writes its warnings to stderr
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw InputError(path.string() + ": expected at least 3 channels");
    RgbImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.pixels.resize(std::size_t(spec.width) * spec.height * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
        const std::string library = quiet.text();  // libpng's reason, if it gave one
        throw InputError(path.string() + ": cannot read image: " + in->geterror() +
                         (library.empty() ? "" : " (" + library + ")"));
    }
    for (const auto& p : spec.extra_attribs)
        img.metadata[p.name().string()] = p.get_string();
    in->close();
    return img;
}

}  // namespace lamina::render
