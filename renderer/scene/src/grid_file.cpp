#include "lamina/scene/grid_file.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "lamina/core/input_file.h"
#include "lamina/core/json_reader.h"

namespace lamina::render {

namespace {

/// "size": three integers in [1, kMaxGridAxis] whose product is at most kMaxGridValues.
DensityGrid readSize(const JsonReader& r) {
    const Json* size = r.has("size") ? &r.value().at("size") : nullptr;
    if (!size) r.failAt("size", "missing; expected [nx, ny, nz]");
    const std::string expected =
        "expected [nx, ny, nz], three integers in [1, " + std::to_string(kMaxGridAxis) + "]";
    if (!size->is_array() || size->size() != 3)
        r.failAt("size", expected + ", got " + shortDump(*size));
    std::int64_t n[3];
    for (std::size_t i = 0; i < 3; ++i) {
        const Json& v = (*size)[i];
        if (!v.is_number_integer() || v.get<std::int64_t>() < 1 ||
            v.get<std::int64_t>() > kMaxGridAxis)
            r.failAt("size", expected + ", got " + shortDump(*size));
        n[i] = v.get<std::int64_t>();
    }
    if (std::uint64_t(n[0] * n[1] * n[2]) > kMaxGridValues)
        r.failAt("size", "has " + std::to_string(n[0] * n[1] * n[2]) + " values; at most " +
                             std::to_string(kMaxGridValues) + " are read");
    DensityGrid g;
    g.nx = int(n[0]);
    g.ny = int(n[1]);
    g.nz = int(n[2]);
    // An RGB value per cell (per-channel coefficients, colour_grid.h), the channels together.
    g.channels = int(r.integer("channels", 1, 1, 3));
    if (g.channels == 2) r.failAt("channels", "expected 1 or 3, got 2");
    return g;
}

/// The numbers a grid holds: nx ny nz times its channels.
std::uint64_t count(const DensityGrid& g) {
    return std::uint64_t(g.nx) * std::uint64_t(g.ny) * std::uint64_t(g.nz) *
           std::uint64_t(g.channels);
}

}  // namespace

DensityGrid readInlineGrid(const JsonReader& r) {
    r.expectObject();
    DensityGrid g = readSize(r);
    if (!r.has("values")) r.failAt("values", "missing; expected nx * ny * nz densities");
    const Json& values = r.value().at("values");
    if (!values.is_array() || values.size() != count(g))
        r.failAt("values", "expected an array of " + std::to_string(count(g)) +
                               " densities (nx * ny * nz times channels), got " +
                               (values.is_array() ? std::to_string(values.size()) + " values"
                                                  : shortDump(values)));
    g.values.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        g.values.push_back(
            float(r.checkNumber(values[i], r.childPath("values") + "[" + std::to_string(i) + "]",
                                Range::nonNegative())));
    r.finish();
    return g;
}

DensityGrid readGridFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::uintmax_t bytes = checkInputFile(path, kMaxGridHeaderBytes + 4 * kMaxGridValues);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot be opened");
    std::string header;
    for (char c; header.size() < kMaxGridHeaderBytes && in.get(c) && c != '\n';)
        header += c;
    if (!in || header.size() >= kMaxGridHeaderBytes)
        throw InputError(name + ": expected a lamina grid file: a first line of at most " +
                         std::to_string(kMaxGridHeaderBytes) +
                         " bytes {\"lamina_grid\": 1, \"size\": [nx, ny, nz]}, then the values");
    const JsonSource source{name, path.parent_path()};
    const Json json = parseJsonText(header, source);
    const JsonReader r(json, "", source);
    r.expectObject();
    if (r.integer("lamina_grid", 0, 1, 1) != 1)
        r.failAt("lamina_grid", "missing; expected 1 (the version of the format)");
    DensityGrid g = readSize(r);
    r.finish();
    if (count(g) > kMaxGridValues)
        r.failAt("channels", "make " + std::to_string(count(g)) + " values; at most " +
                                 std::to_string(kMaxGridValues) + " are read");
    const std::uint64_t dataBytes = 4 * count(g), headerBytes = header.size() + 1;
    if (bytes != headerBytes + dataBytes)
        throw InputError(name + ": expected " + std::to_string(dataBytes) + " bytes of float32 (" +
                         std::to_string(g.nx) + " x " + std::to_string(g.ny) + " x " +
                         std::to_string(g.nz) + " values) after the header, got " +
                         std::to_string(std::int64_t(bytes) - std::int64_t(headerBytes)));
    g.values.resize(count(g));
    in.read(reinterpret_cast<char*>(g.values.data()), std::streamsize(dataBytes));
    if (!in) throw InputError(name + ": the values end early");
    for (std::size_t i = 0; i < g.values.size(); ++i) {
        float& v = g.values[i];
        if constexpr (std::endian::native == std::endian::big) {
            std::uint32_t b;
            std::memcpy(&b, &v, 4);
            b = __builtin_bswap32(b);
            std::memcpy(&v, &b, 4);
        }
        if (!(v >= 0.0f) || !std::isfinite(v)) {
            const std::size_t cell = i / std::size_t(g.channels);
            const std::size_t x = cell % std::size_t(g.nx),
                              y = cell / std::size_t(g.nx) % std::size_t(g.ny),
                              z = cell / (std::size_t(g.nx) * std::size_t(g.ny));
            throw InputError(name + ": value " + std::to_string(i) + " (x " + std::to_string(x) +
                             ", y " + std::to_string(y) + ", z " + std::to_string(z) + ") is " +
                             (std::isnan(v) ? std::string("NaN") : formatNumber(double(v))) +
                             ": expected a finite density >= 0");
        }
    }
    return g;
}

}  // namespace lamina::render
