#include "exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfCompressionAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <tuple>

namespace lamina::render {

namespace {

Imath::Box2i box(int x, int y, int width, int height) {
    return Imath::Box2i(Imath::V2i(x, y), Imath::V2i(x + width - 1, y + height - 1));
}

/// A number of an attribute as text, as OpenImageIO gave lamina's metadata (printf's %g).
std::string floatText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

bool writeExrFile(const std::string& file, const ImageToWrite& image, std::string& error) {
    const Imath::Box2i display = box(0, 0, image.fullWidth, image.fullHeight);
    const Imath::Box2i data = box(image.x, image.y, image.width, image.height);
    const std::size_t nc = image.channels.size();
    std::unique_ptr<Imf::OutputFile> out;
    try {
        Imf::Header header(display, data, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y,
                           image.zip ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION);
        for (const std::string& name : image.channels)
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        const ImageMetadata& m = image.metadata;
        for (const auto& [k, v] : m.strings)
            header.insert("lamina:" + k, Imf::StringAttribute(v));
        for (const auto& [k, v] : m.floats)
            header.insert("lamina:" + k, Imf::FloatAttribute(v));
        for (const auto& [k, v] : m.ints)
            header.insert("lamina:" + k, Imf::IntAttribute(v));
        for (const auto& [k, v] : image.attributes)
            header.insert(k, Imf::StringAttribute(v));
        for (const auto& [k, v] : m.matrices)
            header.insert("lamina:" + k, Imf::M44fAttribute(Imath::M44f(
                                             v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8],
                                             v[9], v[10], v[11], v[12], v[13], v[14], v[15])));
        if (const auto& c = image.chromaticities)
            Imf::addChromaticities(
                header,
                Imf::Chromaticities(Imath::V2f((*c)[0], (*c)[1]), Imath::V2f((*c)[2], (*c)[3]),
                                    Imath::V2f((*c)[4], (*c)[5]), Imath::V2f((*c)[6], (*c)[7])));
        // OpenImageIO stamped every EXR it wrote with the time (capDate, its "DateTime").
        const std::time_t now = std::time(nullptr);
        std::tm local{};
        char date[32] = "";
        if (::localtime_r(&now, &local))
            std::strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", &local);
        Imf::addCapDate(header, date);
        out = std::make_unique<Imf::OutputFile>(file.c_str(), header);
    } catch (const std::exception& e) {
        error = std::string("cannot write: ") + e.what();
        return false;
    }
    try {
        Imf::FrameBuffer frame;
        const std::size_t xStride = sizeof(float) * nc,
                          yStride = xStride * std::size_t(image.width);
        for (std::size_t c = 0; c < nc; ++c)
            frame.insert(image.channels[c],
                         Imf::Slice::Make(Imf::FLOAT, image.samples + c, data, xStride, yStride));
        out->setFrameBuffer(frame);
        out->writePixels(image.height);
        out.reset();  // closes the file
    } catch (const std::exception& e) {
        error = std::string("write failed: ") + e.what();
        return false;
    }
    return true;
}

namespace {

/// OpenImageIO's order of an EXR's channels, which lamina's readers of the first channels rely
/// on: by layer (the part before the last '.'; none first), then R, G, B, A, then the rest by
/// name (OpenEXR lists channels by name).
std::vector<std::string> channelOrder(const Imf::ChannelList& list) {
    std::vector<std::tuple<std::string, int, std::string>> keyed;
    for (auto it = list.begin(); it != list.end(); ++it) {
        const std::string name = it.name();
        const std::size_t dot = name.rfind('.');
        const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
        const std::string base = dot == std::string::npos ? name : name.substr(dot + 1);
        const std::string rgba = "RGBA";
        const int special = base.size() == 1 && rgba.find(base[0]) != std::string::npos
                                ? int(rgba.find(base[0]))
                                : 4;
        keyed.emplace_back(layer, special, name);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::string> names;
    for (const auto& k : keyed)
        names.push_back(std::get<2>(k));
    return names;
}

void readAttributes(const Imf::Header& header, ImageHeader& out) {
    for (auto it = header.begin(); it != header.end(); ++it) {
        const std::string name = it.name();
        const Imf::Attribute& a = it.attribute();
        // By the type name the file gives, which is what the attribute's class stores.
        const std::string type = a.typeName();
        const bool lamina = name.rfind("lamina:", 0) == 0;
        const std::string key = lamina ? name.substr(7) : "";
        ImageMetadata& meta = out.laminaMetadata;
        std::string text;
        if (type == "string") {
            const auto* s = static_cast<const Imf::StringAttribute*>(&a);
            text = s->value();
            if (lamina) meta.strings[key] = text;
        } else if (type == "int") {
            const auto* i = static_cast<const Imf::IntAttribute*>(&a);
            text = std::to_string(i->value());
            if (lamina) meta.ints[key] = i->value();
        } else if (type == "float") {
            const auto* f = static_cast<const Imf::FloatAttribute*>(&a);
            text = floatText(f->value());
            if (lamina) meta.floats[key] = f->value();
        } else if (type == "double") {
            const auto* d = static_cast<const Imf::DoubleAttribute*>(&a);
            text = floatText(d->value());
            if (lamina) meta.strings[key] = text;
        } else if (type == "m44f") {
            const auto* m = static_cast<const Imf::M44fAttribute*>(&a);
            std::array<float, 16> v{};
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) {
                    v[std::size_t(r * 4 + c)] = m->value()[r][c];
                    text += (r || c ? ", " : "") + floatText(m->value()[r][c]);
                }
            if (lamina) meta.matrices[key] = v;
        } else if (type == "v2f") {
            const auto* v = static_cast<const Imf::V2fAttribute*>(&a);
            text = floatText(v->value().x) + ", " + floatText(v->value().y);
        } else if (type == "chromaticities") {
            const Imf::Chromaticities& c =
                static_cast<const Imf::ChromaticitiesAttribute*>(&a)->value();
            for (const Imath::V2f& v : {c.red, c.green, c.blue, c.white})
                text += (text.empty() ? "" : ", ") + floatText(v.x) + ", " + floatText(v.y);
        } else if (type == "compression") {
            const auto* z = static_cast<const Imf::CompressionAttribute*>(&a);
            static const char* const names[] = {"none",  "rle", "zips", "zip",  "piz",
                                                "pxr24", "b44", "b44a", "dwaa", "dwab"};
            const int k = int(z->value());
            text = k >= 0 && k < int(std::size(names)) ? names[k] : "unknown";
        } else {
            continue;  // the window, channel list and other structured attributes
        }
        if (name == "oiio:ColorSpace") out.colorSpace = text;
        // Under the names OpenImageIO gave them (what readRgbImage's metadata had before).
        const std::string shown = name == "capDate"            ? "DateTime"
                                  : name == "pixelAspectRatio" ? "PixelAspectRatio"
                                                               : name;
        out.attributes[shown] = text;
    }
}

class ExrReader : public ImageFileReader {
  public:
    explicit ExrReader(const std::string& file) : in_(file.c_str()) {
        const Imf::Header& h = in_.header();
        const Imath::Box2i& dw = h.dataWindow();
        const std::int64_t w = std::int64_t(dw.max.x) - dw.min.x + 1,
                           hgt = std::int64_t(dw.max.y) - dw.min.y + 1;
        header_.x = dw.min.x;
        header_.y = dw.min.y;
        // An empty or inverted window reads as 0 x 0 (the callers refuse it).
        const auto clamp = [](std::int64_t v) {
            return int(std::clamp<std::int64_t>(v, 0, std::numeric_limits<int>::max()));
        };
        header_.width = clamp(w);
        header_.height = clamp(hgt);
        // lamina's files and OpenImageIO's start the display window at (0, 0).
        const Imath::Box2i& display = h.displayWindow();
        header_.fullWidth = clamp(std::int64_t(display.max.x) - display.min.x + 1);
        header_.fullHeight = clamp(std::int64_t(display.max.y) - display.min.y + 1);
        header_.channels = channelOrder(h.channels());
        header_.floatingPoint = false;
        for (auto it = h.channels().begin(); it != h.channels().end(); ++it)
            if (it.channel().type != Imf::UINT) header_.floatingPoint = true;
        header_.eightOrSixteenBit = false;
        readAttributes(h, header_);
    }

    bool read(int channels, float* samples, Failure& failure) override {
        try {
            const Imath::Box2i& dw = in_.header().dataWindow();
            const std::size_t nc = std::size_t(channels);
            const std::size_t xStride = sizeof(float) * nc,
                              yStride = xStride * std::size_t(header_.width);
            Imf::FrameBuffer frame;
            for (std::size_t c = 0; c < nc; ++c)
                frame.insert(header_.channels[c],
                             Imf::Slice::Make(Imf::FLOAT, samples + c, dw, xStride, yStride));
            in_.setFrameBuffer(frame);
            in_.readPixels(dw.min.y, dw.max.y);
            return true;
        } catch (const std::exception& e) {
            failure = {e.what(), ""};
            return false;
        }
    }

  private:
    Imf::InputFile in_;
};

}  // namespace

bool startsLikeExr(const std::string& file) {
    char magic[4] = {};
    std::ifstream in(file, std::ios::binary);
    return in.read(magic, sizeof magic) && Imf::isImfMagic(magic);
}

std::unique_ptr<ImageFileReader> openExrFile(const std::string& file, Failure& failure) {
    try {
        return std::make_unique<ExrReader>(file);
    } catch (const std::exception& e) {
        failure = {e.what(), ""};
        return nullptr;
    }
}

}  // namespace lamina::render
