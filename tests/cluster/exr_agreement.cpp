// exr_agreement A.exr B.exr CHANNEL...: exit 0 when every named channel of A equals B's to
// relative 1e-6 per pixel (with an absolute floor of 1e-12 times the channel's largest |B|,
// for values that are rounding noise around zero), 1 otherwise, naming the worst pixel. The
// cluster test's comparison of a merged image with a single-process render.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Image {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;
};

bool read(const char* path, Image& image) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::fprintf(stderr, "exr_agreement: %s: %s\n", path, OIIO::geterror().c_str());
        return false;
    }
    image.spec = in->spec();
    image.pixels.resize(std::size_t(image.spec.width) * image.spec.height * image.spec.nchannels);
    return in->read_image(0, 0, 0, image.spec.nchannels, OIIO::TypeDesc::FLOAT,
                          image.pixels.data());
}

int channel(const Image& image, const std::string& name) {
    for (int c = 0; c < image.spec.nchannels; ++c)
        if (image.spec.channel_name(c) == name) return c;
    return -1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: exr_agreement A.exr B.exr CHANNEL...\n");
        return 2;
    }
    Image a, b;
    if (!read(argv[1], a) || !read(argv[2], b)) return 1;
    if (a.spec.width != b.spec.width || a.spec.height != b.spec.height) {
        std::fprintf(stderr, "exr_agreement: %s and %s differ in size\n", argv[1], argv[2]);
        return 1;
    }
    const std::size_t n = std::size_t(a.spec.width) * a.spec.height;
    for (int i = 3; i < argc; ++i) {
        const int ca = channel(a, argv[i]), cb = channel(b, argv[i]);
        if (ca < 0 || cb < 0) {
            std::fprintf(stderr, "exr_agreement: channel %s missing\n", argv[i]);
            return 1;
        }
        double largest = 0;
        for (std::size_t p = 0; p < n; ++p)
            largest = std::max(largest, std::abs(double(b.pixels[p * b.spec.nchannels + cb])));
        double worst = 0;
        std::size_t at = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const double x = a.pixels[p * a.spec.nchannels + ca];
            const double y = b.pixels[p * b.spec.nchannels + cb];
            const double excess = std::abs(x - y) / (1e-6 * std::abs(y) + 1e-12 * largest);
            if (!(excess <= worst)) {
                worst = excess;
                at = p;
            }
        }
        const int x = int(at % std::size_t(a.spec.width)), y = int(at / std::size_t(a.spec.width));
        std::printf("%s: largest difference %.3g of the tolerance at pixel (%d, %d)\n", argv[i],
                    worst, x, y);
        if (!(worst <= 1)) return 1;
    }
    return 0;
}
