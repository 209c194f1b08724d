// Mitsuba's binary volume files (.vol): volume_files.h.
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/core/json_reader.h"
#include "lamina/scene/grid_file.h"
#include "lamina/scene/volume_files.h"

namespace lamina::render {

namespace {

constexpr std::size_t kVolHeaderBytes = 48;

std::uint32_t littleEndian32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
           std::uint32_t(b[3]) << 24;
}

float littleEndianFloat(const unsigned char* b) {
    return std::bit_cast<float>(littleEndian32(b));
}

}  // namespace

bool isMitsubaVolume(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[3] = {};
    return in.read(magic, 3) && std::memcmp(magic, "VOL", 3) == 0;
}

MitsubaVolume readMitsubaVolume(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::uintmax_t bytes =
        checkInputFile(path, kVolHeaderBytes + 3 * 4 * std::uintmax_t(kMaxGridValues));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot be opened");
    unsigned char h[kVolHeaderBytes];
    if (!in.read(reinterpret_cast<char*>(h), kVolHeaderBytes))
        throw InputError(name + ": expected a Mitsuba volume: a 48-byte header, got " +
                         std::to_string(bytes) + " bytes");
    if (std::memcmp(h, "VOL", 3) != 0 || h[3] != 3)
        throw InputError(name +
                         ": expected a Mitsuba volume: the bytes 'V', 'O', 'L', 3 (version 3)");
    if (littleEndian32(h + 4) != 1)
        throw InputError(name + ": encoding " +
                         std::to_string(std::int32_t(littleEndian32(h + 4))) +
                         ": expected 1 (float32), the only encoding Mitsuba 3 reads");
    std::int64_t n[3];
    for (int a = 0; a < 3; ++a) {
        n[a] = std::int32_t(littleEndian32(h + 8 + 4 * a));
        if (n[a] < 1 || n[a] > kMaxGridAxis)
            throw InputError(name + ": resolution " + std::to_string(n[a]) +
                             " along an axis: expected 1 to " + std::to_string(kMaxGridAxis));
    }
    const std::int64_t channels = std::int32_t(littleEndian32(h + 20));
    if (channels != 1 && channels != 3)
        throw InputError(name + ": " + std::to_string(channels) +
                         " channels: expected 1 or 3 (6-channel volumes are not read)");
    const std::uint64_t count = std::uint64_t(n[0] * n[1] * n[2]);
    if (count > kMaxGridValues)
        throw InputError(name + ": " + std::to_string(count) + " cells; at most " +
                         std::to_string(kMaxGridValues) + " are read");
    const std::uint64_t dataBytes = 4 * count * std::uint64_t(channels);
    if (bytes != kVolHeaderBytes + dataBytes)
        throw InputError(name + ": expected " + std::to_string(dataBytes) + " bytes of float32 (" +
                         std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
                         std::to_string(n[2]) + " x " + std::to_string(channels) +
                         " values) after the header, got " +
                         std::to_string(std::int64_t(bytes) - std::int64_t(kVolHeaderBytes)));
    MitsubaVolume v;
    for (int a = 0; a < 3; ++a) {
        v.boxMin[a] = littleEndianFloat(h + 24 + 4 * a);
        v.boxMax[a] = littleEndianFloat(h + 36 + 4 * a);
    }
    v.grid.nx = int(n[0]);
    v.grid.ny = int(n[1]);
    v.grid.nz = int(n[2]);
    v.grid.channels = int(channels);
    std::vector<unsigned char> raw(dataBytes);
    if (!in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(dataBytes)))
        throw InputError(name + ": the values end early");
    v.grid.values.resize(count * std::uint64_t(channels));
    for (std::size_t i = 0; i < v.grid.values.size(); ++i) {
        const float value = littleEndianFloat(raw.data() + 4 * i);
        if (!(value >= 0.0f) || !std::isfinite(value)) {
            const std::size_t cell = i / std::size_t(channels);
            throw InputError(
                name + ": value " + std::to_string(i) + " (x " +
                std::to_string(cell % std::size_t(n[0])) + ", y " +
                std::to_string(cell / std::size_t(n[0]) % std::size_t(n[1])) + ", z " +
                std::to_string(cell / std::size_t(n[0] * n[1])) + ", channel " +
                std::to_string(i % std::size_t(channels)) + ") is " +
                (std::isnan(value) ? std::string("NaN") : formatNumber(double(value))) +
                ": expected a finite value >= 0");
        }
        v.grid.values[i] = value;
    }
    return v;
}

}  // namespace lamina::render
