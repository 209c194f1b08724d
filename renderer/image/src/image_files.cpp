#include "lamina/image/image_files.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "exr_file.h"
#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "oiio_module.h"
#include "png_file.h"

namespace lamina::render {

namespace {

/// The extension in lower case (OpenImageIO chooses a format from it the same way).
std::string extension(const std::filesystem::path& path) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e;
}

bool isPngPath(const std::filesystem::path& path) {
    return extension(path) == ".png";
}

/// An image lamina's own PNG writer handles: 8-bit RGB of a whole image.
bool isPlainRgb8(const ImageToWrite& image) {
    return image.eightBit && image.channels.size() == 3 && image.x == 0 && image.y == 0 &&
           image.width == image.fullWidth && image.height == image.fullHeight;
}

bool writePngFile(const std::string& file, const ImageToWrite& image, std::string& error) {
    std::string bytes;
    try {
        bytes = encodePngRgb8(image.width, image.height, image.samples);
    } catch (const std::exception& e) {
        error = std::string("write failed: ") + e.what();
        return false;
    }
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) {
        error = "cannot write: cannot create " + file;
        return false;
    }
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) {
        error = "write failed: " + file + " (disk full?)";
        return false;
    }
    return true;
}

}  // namespace

bool isExrPath(const std::filesystem::path& path) {
    return extension(path) == ".exr";
}

std::unique_ptr<ImageFileReader> openImageFile(const std::filesystem::path& path,
                                               Failure& failure) {
    // By the extension and the content, as OpenImageIO chose: a file named .exr that is not one
    // (a PNG renamed, a broken file) goes to OpenImageIO's other readers, and its messages.
    if (isExrPath(path) && startsLikeExr(path.string())) return openExrFile(path.string(), failure);

    // Everything else through OpenImageIO: the reader of the module, behind this interface.
    class ModuleReader : public ImageFileReader {
      public:
        ModuleReader(const oiio_images::Functions& f, oiio_images::Reader* r) : f_(f), r_(r) {}
        ~ModuleReader() override { f_.close(r_); }
        ModuleReader(const ModuleReader&) = delete;
        ModuleReader& operator=(const ModuleReader&) = delete;
        ImageHeader& mutableHeader() { return header_; }
        bool read(int channels, float* samples, Failure& why) override {
            return f_.read(r_, channels, samples, why);
        }

      private:
        const oiio_images::Functions& f_;
        oiio_images::Reader* r_;
    };
    const oiio_images::Functions& f = oiioModule(path, "reading");
    ImageHeader header;
    oiio_images::Reader* r = f.open(path.string(), header, failure);
    if (!r) return nullptr;
    auto reader = std::make_unique<ModuleReader>(f, r);
    reader->mutableHeader() = std::move(header);
    return reader;
}

bool canWriteImageFormat(const std::filesystem::path& path) {
    if (isExrPath(path) || isPngPath(path)) return true;
    return oiioModule(path, "writing").canWrite(path.string());
}

void writeImageFile(const std::filesystem::path& path, const ImageToWrite& image) {
    TemporaryFile tmp(path);  // removed if anything below fails
    std::string error;
    bool ok = false;
    if (isExrPath(path) && !image.eightBit)
        ok = writeExrFile(tmp.path().string(), image, error);
    else if (isPngPath(path) && isPlainRgb8(image))
        ok = writePngFile(tmp.path().string(), image, error);
    else
        ok = oiioModule(path, "writing").write(path.string(), tmp.path().string(), image, error);
    if (!ok) throw InputError(path.string() + ": " + error);
    tmp.commit();
}

ImageToWrite floatImage(int width, int height, const std::vector<std::string>& channels,
                        const std::vector<float>& data, const ImageMetadata& metadata) {
    ImageToWrite image;
    image.width = image.fullWidth = width;
    image.height = image.fullHeight = height;
    image.channels = channels;
    image.zip = true;  // OpenImageIO's default for EXR, which these files had before
    image.metadata = metadata;
    image.samples = data.data();
    return image;
}

/// Places the image at `window` of a fullWidth x fullHeight image.
void setDataWindow(ImageToWrite& image, const PixelBounds& window, int fullWidth, int fullHeight) {
    image.x = window.x0;
    image.y = window.y0;
    image.width = window.width();
    image.height = window.height();
    image.fullWidth = fullWidth;
    image.fullHeight = fullHeight;
}

/// An 8-bit RGB image of display-ready values.
ImageToWrite rgb8Image(int width, int height, const std::vector<float>& rgb) {
    ImageToWrite image;
    image.width = image.fullWidth = width;
    image.height = image.fullHeight = height;
    image.channels = {"R", "G", "B"};
    image.eightBit = true;
    image.samples = rgb.data();
    return image;
}

}  // namespace lamina::render
