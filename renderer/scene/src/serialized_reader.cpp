// Mitsuba's serialized meshes (mesh_files.h), the format of mitsuba3 src/shapes/serialized.cpp
// in its versions 3 and 4 (Mitsuba 0.5 and later, and what Mitsuba 3 scenes ship): a file of
// meshes, each a little-endian header (uint16 0x041C, uint16 version) and a zlib stream of
//   uint32 flags (0x0001 normals, 0x0002 uvs, 0x0008 colours, 0x2000 doubles),
//   version 4: the shape's name, null-terminated,
//   uint64 vertex count V, uint64 triangle count F,
//   3 V positions, [3 V normals], [2 V uvs], [3 V colours] (float, or double with 0x2000),
//   3 F uint32 vertex indices;
// a file of several meshes ends with their offsets (version 4: uint64, version 3: uint32, one
// per mesh) and a uint32 count. Colours are read and dropped, as Mitsuba 3 drops them.
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <vector>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/scene/mesh_files.h"

namespace lamina::render {

namespace {

constexpr std::uint16_t kSerializedMagic = 0x041C;
/// The decompressed bytes of one mesh that the reader will take (a small file can inflate
/// without end), as for a .ply.gz.
constexpr std::uint64_t kMaxDecompressedMeshBytes = std::uint64_t(1024) * kMiB;
/// Arrays are read in pieces of this many numbers, so that memory grows with the data that
/// arrives, not with the counts a header claims.
constexpr std::uint64_t kChunkNumbers = std::uint64_t(1) << 20;
constexpr std::size_t kMaxShapeNameBytes = 4096;

enum Flags : std::uint32_t {
    kHasNormals = 0x0001,
    kHasUvs = 0x0002,
    kHasColors = 0x0008,
    kDoublePrecision = 0x2000,
};

template <typename T>
T littleEndian(const unsigned char* bytes) {
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
        value |= T(bytes[i]) << (8 * i);
    return value;
}

// One mesh's zlib stream, inflated on demand.
class Inflater {
  public:
    Inflater(const std::string& data, std::size_t offset, const std::string& where)
        : where_(where) {
        stream_.next_in =
            reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + std::ptrdiff_t(offset)));
        stream_.avail_in =
            uInt(std::min<std::size_t>(data.size() - offset, std::numeric_limits<uInt>::max()));
        if (inflateInit(&stream_) != Z_OK) throw InputError(where_ + ": cannot start zlib");
    }
    ~Inflater() { inflateEnd(&stream_); }
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;

    void read(void* out, std::uint64_t bytes, const char* what) {
        total_ += bytes;
        if (total_ > kMaxDecompressedMeshBytes)
            throw InputError(where_ + ": the mesh is larger than " +
                             std::to_string(kMaxDecompressedMeshBytes / kMiB) + " MiB");
        auto* next = static_cast<unsigned char*>(out);
        while (bytes > 0) {
            const uInt chunk = uInt(std::min<std::uint64_t>(bytes, 1u << 30));
            stream_.next_out = next;
            stream_.avail_out = chunk;
            const int status = inflate(&stream_, Z_NO_FLUSH);
            const uInt produced = chunk - stream_.avail_out;
            next += produced;
            bytes -= produced;
            if (bytes == 0) break;
            if (status == Z_STREAM_END || (status == Z_BUF_ERROR && stream_.avail_in == 0))
                throw InputError(where_ + ": the data ends inside the " + what);
            if (status != Z_OK)
                throw InputError(where_ + ": corrupt zlib data in the " + what + " (" +
                                 (stream_.msg ? stream_.msg : "zlib error") + ")");
        }
    }
    template <typename T>
    T value(const char* what) {
        unsigned char bytes[sizeof(T)];
        read(bytes, sizeof(T), what);
        return littleEndian<T>(bytes);
    }
    // `count` numbers (float, or double when `doubles`) as floats.
    std::vector<float> numbers(std::uint64_t count, bool doubles, const char* what) {
        std::vector<float> out;
        std::vector<unsigned char> bytes;
        const std::uint64_t size = doubles ? 8 : 4;
        for (std::uint64_t done = 0; done < count;) {
            const std::uint64_t n = std::min(kChunkNumbers, count - done);
            bytes.resize(n * size);
            read(bytes.data(), n * size, what);
            for (std::uint64_t i = 0; i < n; ++i) {
                if (doubles) {
                    const std::uint64_t bits = littleEndian<std::uint64_t>(&bytes[i * 8]);
                    double d;
                    std::memcpy(&d, &bits, 8);
                    out.push_back(float(d));
                } else {
                    const std::uint32_t bits = littleEndian<std::uint32_t>(&bytes[i * 4]);
                    float f;
                    std::memcpy(&f, &bits, 4);
                    out.push_back(f);
                }
            }
            done += n;
        }
        return out;
    }
    // `count` uint32 indices.
    std::vector<std::uint32_t> indices(std::uint64_t count, const char* what) {
        std::vector<std::uint32_t> out;
        std::vector<unsigned char> bytes;
        for (std::uint64_t done = 0; done < count;) {
            const std::uint64_t n = std::min(kChunkNumbers, count - done);
            bytes.resize(n * 4);
            read(bytes.data(), n * 4, what);
            for (std::uint64_t i = 0; i < n; ++i)
                out.push_back(littleEndian<std::uint32_t>(&bytes[i * 4]));
            done += n;
        }
        return out;
    }

  private:
    z_stream stream_{};
    std::string where_;
    std::uint64_t total_ = 0;
};

// Where mesh `index` starts: 0 for the first, else the offset table at the file's end.
std::size_t meshOffset(const std::string& data, std::uint16_t version, std::uint32_t index,
                       const std::string& where) {
    if (index == 0) return 0;
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    if (data.size() < 8) throw InputError(where + ": no table of meshes at the end of the file");
    const std::uint32_t count = littleEndian<std::uint32_t>(bytes + data.size() - 4);
    if (index >= count)
        throw InputError(where + ": shape_index " + std::to_string(index) +
                         " is out of range (the file has " + std::to_string(count) + " meshes)");
    const std::uint64_t entry = version >= 4 ? 8 : 4;
    const std::uint64_t table = entry * std::uint64_t(count);
    if (table + 4 > data.size())
        throw InputError(where + ": the table of " + std::to_string(count) +
                         " meshes is larger than the file");
    const unsigned char* at = bytes + data.size() - 4 - entry * (count - index);
    const std::uint64_t offset =
        version >= 4 ? littleEndian<std::uint64_t>(at) : littleEndian<std::uint32_t>(at);
    // Written so that an offset near 2^64 cannot wrap around the comparison.
    const std::uint64_t meshesEnd = data.size() - 4 - table;
    if (offset > meshesEnd || meshesEnd - offset < 4)
        throw InputError(where + ": mesh " + std::to_string(index) + " starts at " +
                         std::to_string(offset) + ", past the file's meshes");
    return std::size_t(offset);
}

}  // namespace

void readSerialized(const std::filesystem::path& file, std::uint32_t shapeIndex, MeshDesc& mesh) {
    const std::string data = readInputFile(file, kMaxMeshFileBytes);
    const std::string where = file.string();
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    if (data.size() < 4 || littleEndian<std::uint16_t>(bytes) != kSerializedMagic)
        throw InputError(where + ": not a Mitsuba serialized mesh (no 0x041C header)");
    const std::uint16_t version = littleEndian<std::uint16_t>(bytes + 2);
    if (version != 3 && version != 4)
        throw InputError(where + ": serialized format version " + std::to_string(version) +
                         " is not supported (versions 3 and 4)");
    const std::size_t offset = meshOffset(data, version, shapeIndex, where);
    if (littleEndian<std::uint16_t>(bytes + offset) != kSerializedMagic ||
        littleEndian<std::uint16_t>(bytes + offset + 2) != version)
        throw InputError(where + ": mesh " + std::to_string(shapeIndex) + " at byte " +
                         std::to_string(offset) + " has no header like the file's");
    const std::string meshWhere = where + " (mesh " + std::to_string(shapeIndex) + ")";
    Inflater in(data, offset + 4, meshWhere);
    const std::uint32_t flags = in.value<std::uint32_t>("flags");
    if (version == 4) {
        std::size_t length = 0;
        while (in.value<std::uint8_t>("shape name") != 0)
            if (++length > kMaxShapeNameBytes)
                throw InputError(meshWhere + ": a shape name longer than " +
                                 std::to_string(kMaxShapeNameBytes) + " bytes");
    }
    const std::uint64_t vertices = in.value<std::uint64_t>("vertex count");
    const std::uint64_t triangles = in.value<std::uint64_t>("triangle count");
    // Every vertex is at least 12 bytes, every triangle 12: counts no file within the bound
    // can hold are refused before reading.
    if (vertices == 0 || triangles == 0)
        throw InputError(meshWhere + ": no vertices or no triangles");
    if (vertices > kMaxDecompressedMeshBytes / 12 || triangles > kMaxDecompressedMeshBytes / 12)
        throw InputError(meshWhere + ": " + std::to_string(vertices) + " vertices and " +
                         std::to_string(triangles) + " triangles are more than the reader takes");
    const bool doubles = flags & kDoublePrecision;
    const std::vector<float> positions = in.numbers(3 * vertices, doubles, "positions");
    std::vector<float> normals, uvs;
    if (flags & kHasNormals) normals = in.numbers(3 * vertices, doubles, "normals");
    if (flags & kHasUvs) uvs = in.numbers(2 * vertices, doubles, "texture coordinates");
    if (flags & kHasColors) in.numbers(3 * vertices, doubles, "vertex colours");
    const std::vector<std::uint32_t> indices = in.indices(3 * triangles, "triangles");

    const std::size_t base = mesh.positions.size();
    if (base + vertices > std::numeric_limits<std::uint32_t>::max())
        throw InputError(meshWhere + ": more vertices than 32-bit indices reach");
    for (std::uint64_t v = 0; v < vertices; ++v) {
        mesh.positions.push_back({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
        if (!normals.empty())
            mesh.normals.push_back({normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]});
        if (!uvs.empty()) mesh.uvs.push_back({uvs[2 * v], uvs[2 * v + 1]});
    }
    for (std::uint64_t t = 0; t < triangles; ++t) {
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = indices[3 * t + std::size_t(k)];
            if (i >= vertices)
                throw InputError(meshWhere + ": triangle " + std::to_string(t) +
                                 " refers to vertex " + std::to_string(i) + " of " +
                                 std::to_string(vertices));
            triangle[std::size_t(k)] = std::uint32_t(base) + i;
        }
        mesh.triangles.push_back(triangle);
    }
    if (const auto bad = firstBadVertex(mesh, base)) throw InputError(meshWhere + ": " + *bad);
}

}  // namespace lamina::render
