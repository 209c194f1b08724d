#include "lamina/render/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
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
    for (const auto& [k, v] : metadata.matrices)
        spec.attribute("lamina:" + k, OIIO::TypeMatrix44, v.data());
}

/// Places the image at `window` of a fullWidth x fullHeight image.
void setDataWindow(OIIO::ImageSpec& spec, const PixelBounds& window, int fullWidth,
                   int fullHeight) {
    spec.x = window.x0;
    spec.y = window.y0;
    spec.full_x = spec.full_y = 0;
    spec.full_width = fullWidth;
    spec.full_height = fullHeight;
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
              const ImageMetadata& metadata, bool variance) {
    const int w = film.width(), h = film.height();
    std::vector<std::string> channels = {"R", "G", "B"};
    if (aovs)
        channels.insert(channels.end(), {"Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z",
                                         "Z", "Variance.Y"});
    else if (variance)
        channels.push_back("Variance.Y");
    if (variance) channels.insert(channels.end(), {"Variance.R", "Variance.G", "Variance.B"});
    const std::size_t nc = channels.size();
    OIIO::ImageSpec spec(w, h, int(nc), OIIO::TypeDesc::FLOAT);
    setDataWindow(spec, film.window(), film.fullWidth(), film.fullHeight());
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
            if (variance) {
                const Rgb<double> var = film.varianceOfMeanRgb(x, y);
                for (int c = 0; c < 3; ++c)
                    p[nc - 3 + std::size_t(c)] = float(var[c]);
            }
            if (!aovs) {
                if (variance) p[3] = float(film.varianceOfMean(x, y));
                continue;
            }
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

void writeFloatExr(const std::filesystem::path& path, const PixelBounds& window, int fullWidth,
                   int fullHeight, const std::vector<std::string>& channels,
                   const std::vector<float>& data, const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(window.width(), window.height(), int(channels.size()),
                         OIIO::TypeDesc::FLOAT);
    setDataWindow(spec, window, fullWidth, fullHeight);
    spec.channelnames = channels;
    spec.attribute("compression", "zip");
    addMetadata(spec, metadata);
    writeAtomically(path, spec, data);
}

void writeRgb8(const std::filesystem::path& path, int width, int height,
               const std::vector<float>& rgb) {
    writeAtomically(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), rgb);
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

namespace {

/// The index of channel `name`, or -1.
int channelIndex(const OIIO::ImageSpec& spec, const std::string& name) {
    for (int c = 0; c < spec.nchannels; ++c)
        if (spec.channel_name(c) == name) return c;
    return -1;
}

/// An 8- or 16-bit file is sRGB-encoded unless it says otherwise (PNG, JPEG); a float file is
/// linear unless it says it is sRGB.
bool isSrgbEncoded(const OIIO::ImageSpec& spec) {
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(cs.begin(), cs.end(), cs.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (cs.find("srgb") != std::string::npos && cs.find("lin") == std::string::npos) return true;
    const bool integer = !spec.format.is_floating_point();
    return integer && cs.empty();
}

double srgbToLinear(double e) {
    // The inverse of the sRGB transfer function (IEC 61966-2-1).
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

}  // namespace

RgbImage readRgbImage(const std::filesystem::path& path) {
    checkInputFile(path, kMaxImageFileBytes);
    const StderrCapture quiet;  // libpng writes its warnings to stderr
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    // A small header can claim any resolution: refuse before allocating for it.
    if (std::uintmax_t(std::max(spec.width, 0)) * std::uintmax_t(std::max(spec.height, 0)) >
        kMaxImagePixels)
        throw InputError(path.string() + ": " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height) + " pixels, more than the limit of " +
                         std::to_string(kMaxImagePixels));
    // By name, not by position: an EXR's channels are stored sorted (A before B, G, R, and
    // AOV layers such as Albedo.R before R).
    const int channels[3] = {channelIndex(spec, "R"), channelIndex(spec, "G"),
                             channelIndex(spec, "B")};
    if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
        std::string names;
        for (int c = 0; c < spec.nchannels; ++c)
            names += std::string(c ? ", " : "") + std::string(spec.channel_name(c));
        throw InputError(path.string() + ": expected channels R, G and B, found " +
                         (names.empty() ? std::string("none") : names));
    }
    RgbImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.displayReferred = isSrgbEncoded(spec);
    const std::size_t nc = std::size_t(spec.nchannels), n = std::size_t(spec.width) * spec.height;
    std::vector<float> all(n * nc);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) {
        const std::string library = quiet.text();  // libpng's reason, if it gave one
        throw InputError(path.string() + ": cannot read image: " + in->geterror() +
                         (library.empty() ? "" : " (" + library + ")"));
    }
    img.pixels.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = all[i * nc + std::size_t(channels[c])];
            img.pixels[i * 3 + std::size_t(c)] =
                img.displayReferred ? float(srgbToLinear(double(v))) : v;
        }
    for (const auto& p : spec.extra_attribs)
        img.metadata[p.name().string()] = p.get_string();
    in->close();
    return img;
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
