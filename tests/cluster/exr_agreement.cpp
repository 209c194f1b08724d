// exr_agreement A.exr B.exr CHANNEL...: exit 0 when every named channel of A equals B's to
// relative 1e-6 per pixel (with an absolute floor of 1e-12 times the channel's largest |B|,
// for values that are rounding noise around zero), 1 otherwise, naming the worst pixel. The
// cluster test's comparison of a merged image with a single-process render.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "lamina/output/image_output.h"

namespace {

bool read(const char* path, lamina::render::FloatImage& image) {
    try {
        image = lamina::render::readFloatImage(path);
        return true;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "exr_agreement: %s\n", e.what());
        return false;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: exr_agreement A.exr B.exr CHANNEL...\n");
        return 2;
    }
    lamina::render::FloatImage a, b;
    if (!read(argv[1], a) || !read(argv[2], b)) return 1;
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "exr_agreement: %s and %s differ in size\n", argv[1], argv[2]);
        return 1;
    }
    const std::size_t n = std::size_t(a.width) * a.height;
    for (int i = 3; i < argc; ++i) {
        const int ca = a.channel(argv[i]), cb = b.channel(argv[i]);
        if (ca < 0 || cb < 0) {
            std::fprintf(stderr, "exr_agreement: channel %s missing\n", argv[i]);
            return 1;
        }
        double largest = 0;
        for (std::size_t p = 0; p < n; ++p)
            largest = std::max(
                largest, std::abs(double(b.samples[p * b.channels.size() + std::size_t(cb)])));
        double worst = 0;
        std::size_t at = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const double x = a.samples[p * a.channels.size() + std::size_t(ca)];
            const double y = b.samples[p * b.channels.size() + std::size_t(cb)];
            const double excess = std::abs(x - y) / (1e-6 * std::abs(y) + 1e-12 * largest);
            if (!(excess <= worst)) {
                worst = excess;
                at = p;
            }
        }
        const int x = int(at % std::size_t(a.width)), y = int(at / std::size_t(a.width));
        std::printf("%s: largest difference %.3g of the tolerance at pixel (%d, %d)\n", argv[i],
                    worst, x, y);
        if (!(worst <= 1)) return 1;
    }
    return 0;
}
