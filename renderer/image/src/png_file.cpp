// The format is the PNG specification (W3C, Portable Network Graphics Specification, Second
// Edition, 2003; first published as RFC 2083): the 8-byte signature (section 5.2), chunks of
// a 4-byte big-endian length, a 4-byte type, the data and a CRC-32 of type and data (5.3);
// IHDR (11.2.2), sRGB (11.3.3.5), IDAT holding one zlib stream (RFC 1950) of the filtered
// scanlines (10, 7.3), IEND (11.2.5). Each scanline starts with its filter type, 0 (none:
// section 9.2), so the image data is simply the rows one after the other.
#include "png_file.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace lamina::render {

namespace {

void putBigEndian(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(char((v >> shift) & 0xff));
}

void putChunk(std::string& out, const char type[4], const std::string& data) {
    putBigEndian(out, std::uint32_t(data.size()));
    const std::size_t start = out.size();
    out.append(type, 4);
    out += data;
    // The CRC covers the type and the data, not the length (section 5.3).
    const uLong crc =
        ::crc32(::crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(out.data() + start),
                uInt(out.size() - start));
    putBigEndian(out, std::uint32_t(crc));
}

std::uint8_t toByte(float v) {
    if (!(v > 0)) return 0;  // NaN too
    return std::uint8_t(std::lround(std::min(v, 1.0f) * 255.0f));
}

}  // namespace

std::string encodePngRgb8(int width, int height, const float* rgb) {
    const std::size_t rowBytes = std::size_t(width) * 3 + 1;  // the filter-type byte first
    std::vector<Bytef> raw(rowBytes * std::size_t(height));
    for (int y = 0; y < height; ++y) {
        Bytef* row = &raw[rowBytes * std::size_t(y)];
        row[0] = 0;  // filter type None
        for (std::size_t i = 0; i < std::size_t(width) * 3; ++i)
            row[1 + i] = toByte(rgb[std::size_t(y) * std::size_t(width) * 3 + i]);
    }
    uLongf packedSize = ::compressBound(uLong(raw.size()));
    std::string packed(packedSize, '\0');
    if (::compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize, raw.data(),
                    uLong(raw.size()), Z_DEFAULT_COMPRESSION) != Z_OK)
        throw std::runtime_error("zlib could not compress the image");
    packed.resize(packedSize);

    std::string png("\x89PNG\r\n\x1a\n", 8);
    std::string header;
    putBigEndian(header, std::uint32_t(width));
    putBigEndian(header, std::uint32_t(height));
    // Bit depth 8, colour type 2 (truecolour), compression 0, filter method 0, no interlace.
    header += std::string("\x08\x02\x00\x00\x00", 5);
    putChunk(png, "IHDR", header);
    putChunk(png, "sRGB", std::string(1, '\0'));  // rendering intent 0, perceptual
    putChunk(png, "IDAT", packed);
    putChunk(png, "IEND", "");
    return png;
}

}  // namespace lamina::render
