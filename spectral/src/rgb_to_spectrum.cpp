#include "lamina/spectral/rgb_to_spectrum.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"

// The table generated at build time (tools/generate_rgb_to_spectrum.cpp), embedded as bytes
// with the assembler's .incbin: no 10 MB source file to compile, nothing to find at run time.
#define LAMINA_STRINGIFY2(x) #x
#define LAMINA_STRINGIFY(x) LAMINA_STRINGIFY2(x)
__asm__(
    ".section .rodata\n"
    ".balign 16\n"
    ".global lamina_rgb_to_spectrum_blob\n"
    "lamina_rgb_to_spectrum_blob:\n"
    ".incbin \"" LAMINA_RGB_TO_SPECTRUM_FILE
    "\"\n"
    ".global lamina_rgb_to_spectrum_blob_end\n"
    "lamina_rgb_to_spectrum_blob_end:\n"
    ".byte 0\n"
    ".previous\n");
extern "C" const unsigned char lamina_rgb_to_spectrum_blob[];
extern "C" const unsigned char lamina_rgb_to_spectrum_blob_end[];

namespace lamina {

const RgbToSpectrumTable& RgbToSpectrumTable::rec709() {
    static const RgbToSpectrumTable table = [] {
        const unsigned char* p = lamina_rgb_to_spectrum_blob;
        const std::size_t bytes = std::size_t(lamina_rgb_to_spectrum_blob_end - p);
        std::int32_t header[2];
        std::memcpy(header, p, sizeof header);
        const int res = header[1];
        const std::size_t floats = std::size_t(res) + std::size_t(3) * res * res * res * 3;
        if (header[0] != 0x4247524c || bytes != sizeof header + floats * sizeof(float))
            throw std::runtime_error("the embedded RGB -> spectrum table is corrupt");
        // .balign 16 and the 8-byte header keep the floats 4-byte aligned.
        const auto* f = reinterpret_cast<const float*>(p + sizeof header);
        return RgbToSpectrumTable(res, {f, std::size_t(res)},
                                  {f + res, std::size_t(3) * res * res * res * 3});
    }();
    return table;
}

SigmoidPolynomial RgbToSpectrumTable::lookup(Rgb<double> rgb) const {
    // Written so that a NaN component becomes 0: std::clamp would pass it on to the table
    // indices below (out of the table). Components above 1 are 1.
    for (int c = 0; c < 3; ++c)
        rgb[c] = rgb[c] > 0.0 ? std::min(rgb[c], 1.0) : 0.0;
    if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) return SigmoidPolynomial::constant(rgb[0]);
    const int l = rgb[0] >= rgb[1] ? (rgb[0] >= rgb[2] ? 0 : 2) : (rgb[1] >= rgb[2] ? 1 : 2);
    const double z = rgb[l];
    const double x = rgb[(l + 1) % 3] / z * double(res_ - 1);
    const double y = rgb[(l + 2) % 3] / z * double(res_ - 1);
    const int xi = std::min(int(x), res_ - 2), yi = std::min(int(y), res_ - 2);
    const auto it = std::upper_bound(scale_.begin(), scale_.end(), float(z));
    const int zi = std::clamp(int(it - scale_.begin()) - 1, 0, res_ - 2);
    const double dx = x - xi, dy = y - yi;
    const double dz = (z - double(scale_[std::size_t(zi)])) /
                      double(scale_[std::size_t(zi) + 1] - scale_[std::size_t(zi)]);
    double c[3] = {0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
        const int ox = corner & 1, oy = (corner >> 1) & 1, oz = (corner >> 2) & 1;
        const double w = (ox ? dx : 1 - dx) * (oy ? dy : 1 - dy) * (oz ? dz : 1 - dz);
        if (w == 0) continue;
        const std::size_t idx =
            ((((std::size_t(l) * res_ + std::size_t(zi + oz)) * res_ + std::size_t(yi + oy)) *
                  res_ +
              std::size_t(xi + ox)) *
             3);
        for (int k = 0; k < 3; ++k)
            c[k] += w * double(data_[idx + std::size_t(k)]);
    }
    return {c[0], c[1], c[2]};
}

Rgb<double> reflectanceColor(const std::function<double(double)>& reflectance) {
    const Vec3d xyz =
        integrateAgainstCmf([&](double nm) { return reflectance(nm) * d65Normalized(nm); }) /
        cieYIntegral();
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
    return {std::clamp(rgb.x, 0.0, 1.0), std::clamp(rgb.y, 0.0, 1.0), std::clamp(rgb.z, 0.0, 1.0)};
}

double d65Normalized(double nm) {
    static const TabulatedCurve* d65 = findCieIlluminant("D65");
    static const double scale = [] {
        const Vec3d xyz = integrateAgainstCmf([](double l) { return (*d65)(l); });
        return cieYIntegral() / xyz.y;
    }();
    return (*d65)(nm)*scale;
}

RgbSpectrum::RgbSpectrum(const Rgb<double>& rgb, RgbSpectrumKind kind) {
    const RgbToSpectrumTable& table = RgbToSpectrumTable::rec709();
    if (kind == RgbSpectrumKind::Reflectance) {
        poly_ = table.lookup(rgb);
        return;
    }
    const double m = std::max({rgb[0], rgb[1], rgb[2], 0.0});
    scale_ = 2.0 * m;
    poly_ = scale_ > 0 ? table.lookup(rgb / scale_) : SigmoidPolynomial::constant(0.0);
    illuminant_ = kind == RgbSpectrumKind::Illuminant;
}

double RgbSpectrum::operator()(double nm) const {
    const double v = scale_ * poly_(nm);
    return illuminant_ ? v * d65Normalized(nm) : v;
}

}  // namespace lamina
