#include "lamina/scene/mesh_files.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include <zlib.h>

#include "lamina/core/error.h"
#include "lamina/core/gzip_file.h"
#include "lamina/core/input_file.h"

namespace lamina::render {

namespace {

// A gzip-compressed PLY (.ply.gz, as pbrt-v4 scenes ship them) is decompressed into memory,
// at most this many bytes (gzip_file.h).
constexpr std::uintmax_t kMaxDecompressedPlyBytes = 1024 * kMiB;

std::unique_ptr<std::istream> openPly(const std::filesystem::path& file, std::uintmax_t& size) {
    if (isGzipPath(file)) {
        std::string data = readGzipFile(file, kMaxMeshFileBytes, kMaxDecompressedPlyBytes, "PLY");
        size = data.size();
        return std::make_unique<std::istringstream>(std::move(data), std::ios::binary);
    }
    size = checkInputFile(file, kMaxMeshFileBytes);
    return std::make_unique<std::ifstream>(file, std::ios::binary);
}

enum class Format { Ascii, BinaryLittle, BinaryBig };

// A scalar type of the header, resolved once: the body is read by a switch, not by comparing
// type names for every number (which took most of a 10-million-triangle file's reading time).
enum class Scalar : std::uint8_t {
    None,
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Float32,
    Float64
};

Scalar scalarType(const std::string& t) {
    if (t == "char" || t == "int8") return Scalar::Int8;
    if (t == "uchar" || t == "uint8") return Scalar::UInt8;
    if (t == "short" || t == "int16") return Scalar::Int16;
    if (t == "ushort" || t == "uint16") return Scalar::UInt16;
    if (t == "int" || t == "int32") return Scalar::Int32;
    if (t == "uint" || t == "uint32") return Scalar::UInt32;
    if (t == "float" || t == "float32") return Scalar::Float32;
    if (t == "double" || t == "float64") return Scalar::Float64;
    return Scalar::None;
}

std::size_t scalarSize(Scalar s) {
    switch (s) {
        case Scalar::Int8:
        case Scalar::UInt8:
            return 1;
        case Scalar::Int16:
        case Scalar::UInt16:
            return 2;
        case Scalar::Int32:
        case Scalar::UInt32:
        case Scalar::Float32:
            return 4;
        case Scalar::Float64:
            return 8;
        case Scalar::None:
            break;
    }
    return 0;
}

struct Property {
    std::string name;
    Scalar type = Scalar::None;       // scalar type, or the item type of a list
    Scalar countType = Scalar::None;  // list: the count's type; None for scalars
    bool isList() const { return countType != Scalar::None; }
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

// The binary body, read through a buffer of its own: a number is a few bytes copied out of it,
// not a call through the stream.
class ByteSource {
  public:
    explicit ByteSource(std::istream& in) : in_(in), buffer_(kChunk) {}

    /// Copies the next n (<= 8) bytes to `out`; false at the end of the data.
    bool take(unsigned char* out, std::size_t n) {
        if (size_ - position_ < n && !refill(n)) return false;
        std::memcpy(out, buffer_.data() + position_, n);
        position_ += n;
        return true;
    }

  private:
    static constexpr std::size_t kChunk = 1 << 20;
    bool refill(std::size_t n) {
        const std::size_t left = size_ - position_;
        std::memmove(buffer_.data(), buffer_.data() + position_, left);
        in_.read(reinterpret_cast<char*>(buffer_.data() + left), std::streamsize(kChunk - left));
        size_ = left + std::size_t(in_.gcount());
        position_ = 0;
        return size_ >= n;
    }
    std::istream& in_;
    std::vector<unsigned char> buffer_;
    std::size_t position_ = 0, size_ = 0;
};

// An integer read from a file, for messages: "99999999999", never a wrapped 32-bit value.
std::string integerText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

// The header's element count: a plain decimal integer (a "-1" read into a size_t would be
// 2^64 - 1 elements).
bool parseCount(const std::string& word, std::size_t& count) {
    if (word.empty() || word.size() > 19 || word.find_first_not_of("0123456789") != word.npos)
        return false;
    count = std::size_t(std::stoull(word));
    return true;
}

class PlyReader {
  public:
    explicit PlyReader(const std::filesystem::path& file)
        : file_(file), stream_(openPly(file, size_)), in_(*stream_) {
        if (!in_) fail("cannot open the PLY file");
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(file_.string() + ": " + what);
    }

    void readHeader() {
        std::string line;
        if (!std::getline(in_, line) || line.substr(0, 3) != "ply")
            fail("not a PLY file (no 'ply' magic)");
        while (std::getline(in_, line)) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::istringstream s(line);
            std::string word;
            s >> word;
            if (word == "format") {
                std::string f;
                s >> f;
                if (f == "ascii")
                    format_ = Format::Ascii;
                else if (f == "binary_little_endian")
                    format_ = Format::BinaryLittle;
                else if (f == "binary_big_endian")
                    format_ = Format::BinaryBig;
                else
                    fail("unknown format \"" + f + "\"");
            } else if (word == "element") {
                Element e;
                std::string count;
                s >> e.name >> count;
                if (!s || !parseCount(count, e.count)) fail("malformed element line: " + line);
                elements_.push_back(e);
            } else if (word == "property") {
                if (elements_.empty()) fail("property before any element");
                Property p;
                std::string t, countType, itemType;
                s >> t;
                if (t == "list") {
                    s >> countType >> itemType >> p.name;
                    p.countType = scalarType(countType);
                    p.type = scalarType(itemType);
                    if (p.countType == Scalar::None) p.type = Scalar::None;
                } else {
                    p.type = scalarType(t);
                    s >> p.name;
                }
                if (!s || p.type == Scalar::None)
                    fail("malformed or unsupported property line: " + line);
                elements_.back().properties.push_back(p);
            } else if (word == "end_header") {
                checkCounts();
                return;
            }
        }
        fail("no end_header");
    }

    // Counts that lie (more elements than the file holds) must fail before the reader loops
    // over them: each element takes at least one byte per scalar in binary (the sizes of its
    // scalars and list counts), and at least a digit and a separator per scalar in ASCII.
    void checkCounts() {
        const std::uintmax_t headerEnd = std::uintmax_t(std::max<std::streamoff>(in_.tellg(), 0));
        const std::uintmax_t body = size_ > headerEnd ? size_ - headerEnd : 0;
        std::uintmax_t needed = 0;
        for (const Element& e : elements_) {
            std::uintmax_t perElement = 0;
            for (const Property& p : e.properties)
                perElement +=
                    format_ == Format::Ascii ? 2 : scalarSize(p.isList() ? p.countType : p.type);
            const std::uintmax_t room = body - std::min(body, needed) + 1;
            if (perElement > 0 && e.count > room / perElement)
                fail("element " + e.name + ": unexpected end of data: the header says " +
                     std::to_string(e.count) + " elements, more than the " + std::to_string(body) +
                     " bytes after the header can hold");
            needed += e.count * perElement;
        }
    }

    std::size_t vertexCount() const {
        for (const Element& e : elements_)
            if (e.name == "vertex") return e.count;
        return 0;
    }

    double readScalar(Scalar type) {
        if (format_ == Format::Ascii) {
            double v;
            if (!(in_ >> v)) fail(location() + ": unexpected end of data or a non-number");
            return v;
        }
        unsigned char buf[8];
        const std::size_t n = scalarSize(type);
        if (!bytes_->take(buf, n)) fail(location() + ": unexpected end of data");
        if (swap_) std::reverse(buf, buf + n);
        auto as = [&](auto v) {
            std::memcpy(&v, buf, sizeof v);
            return double(v);
        };
        switch (type) {
            case Scalar::Int8:
                return as(std::int8_t{});
            case Scalar::UInt8:
                return as(std::uint8_t{});
            case Scalar::Int16:
                return as(std::int16_t{});
            case Scalar::UInt16:
                return as(std::uint16_t{});
            case Scalar::Int32:
                return as(std::int32_t{});
            case Scalar::UInt32:
                return as(std::uint32_t{});
            case Scalar::Float32:
                return as(float{});
            case Scalar::Float64:
            case Scalar::None:
                break;
        }
        return as(double{});
    }

    /// "face 12": the element being read, for messages (made only when one is written).
    std::string location() const {
        return element_ ? element_->name + " " + std::to_string(index_) : std::string("header");
    }

    void read(MeshDesc& mesh) {
        readHeader();
        if (format_ != Format::Ascii) {
            bytes_.emplace(in_);
            swap_ = (format_ == Format::BinaryBig) == (std::endian::native == std::endian::little);
        }
        const std::uint32_t base = std::uint32_t(mesh.positions.size());
        const std::size_t vertices = vertexCount();
        if (vertices > std::numeric_limits<std::uint32_t>::max() - base)
            fail("element vertex: " + std::to_string(vertices) +
                 " vertices, more than a mesh can index with 32 bits");
        for (const Element& e : elements_) {
            const bool vertex = e.name == "vertex", face = e.name == "face";
            auto index = [&](const char* a, const char* b = nullptr) {
                for (std::size_t i = 0; i < e.properties.size(); ++i)
                    if (e.properties[i].name == a || (b && e.properties[i].name == b))
                        return int(i);
                return -1;
            };
            const int px = index("x"), py = index("y"), pz = index("z");
            const int nx = index("nx"), ny = index("ny"), nz = index("nz");
            const int tu = index("u", "s"), tv = index("v", "t");
            const int list = index("vertex_indices", "vertex_index");
            if (vertex && (px < 0 || py < 0 || pz < 0)) fail("vertex element without x, y, z");
            if (face && list < 0) fail("face element without vertex_indices");
            const bool normals = vertex && nx >= 0 && ny >= 0 && nz >= 0;
            const bool uvs = vertex && tu >= 0 && tv >= 0;
            std::vector<double> values(e.properties.size());
            std::vector<std::uint32_t> polygon;
            element_ = &e;
            if (vertex) {
                mesh.positions.reserve(mesh.positions.size() + e.count);
                if (normals) mesh.normals.reserve(mesh.normals.size() + e.count);
                if (uvs) mesh.uvs.reserve(mesh.uvs.size() + e.count);
            }
            if (face) mesh.triangles.reserve(mesh.triangles.size() + e.count);
            // An element without properties occupies no bytes: nothing to read, however many.
            const std::size_t count = e.properties.empty() ? 0 : e.count;
            for (std::size_t k = 0; k < count; ++k) {
                index_ = k;
                polygon.clear();
                for (std::size_t p = 0; p < e.properties.size(); ++p) {
                    const Property& prop = e.properties[p];
                    if (!prop.isList()) {
                        values[p] = readScalar(prop.type);
                        continue;
                    }
                    const double n = readScalar(prop.countType);
                    const bool indices = face && int(p) == list;
                    if (!(n >= 0 && n <= 1e6 && n == std::floor(n)))
                        fail(e.name + " " + std::to_string(k) + ": implausible list length " +
                             integerText(n));
                    if (indices && n > double(vertices))
                        fail("face " + std::to_string(k) + ": lists " + integerText(n) +
                             " vertices, more than the " + std::to_string(vertices) +
                             " of element vertex");
                    for (int i = 0; i < int(n); ++i) {
                        const double v = readScalar(prop.type);
                        if (!indices) continue;
                        if (!(v >= 0 && v < double(vertices) && v == std::floor(v)))
                            fail("face " + std::to_string(k) + ": face index " +
                                 (std::isfinite(v) ? integerText(v) : std::string("nan")) +
                                 " is out of range [0, " + std::to_string(vertices) + ")");
                        polygon.push_back(base + std::uint32_t(v));
                    }
                }
                if (vertex) {
                    mesh.positions.emplace_back(float(values[std::size_t(px)]),
                                                float(values[std::size_t(py)]),
                                                float(values[std::size_t(pz)]));
                    if (normals)
                        mesh.normals.emplace_back(float(values[std::size_t(nx)]),
                                                  float(values[std::size_t(ny)]),
                                                  float(values[std::size_t(nz)]));
                    if (uvs)
                        mesh.uvs.emplace_back(float(values[std::size_t(tu)]),
                                              float(values[std::size_t(tv)]));
                }
                if (face) {
                    if (polygon.size() < 3)
                        fail("face " + std::to_string(k) + " has fewer than 3 vertices");
                    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
                        mesh.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
                }
            }
        }
        // Every index was checked against the header's vertex count, which the vertex
        // element then delivered in full (a short file fails in readScalar).
        if (mesh.triangles.empty()) fail("no faces");
        if (const auto bad = firstBadVertex(mesh, base)) fail(*bad);
    }

  private:
    std::filesystem::path file_;
    std::uintmax_t size_ = 0;  ///< decompressed, for a .ply.gz
    std::unique_ptr<std::istream> stream_;
    std::istream& in_;
    Format format_ = Format::Ascii;
    std::vector<Element> elements_;
    std::optional<ByteSource> bytes_;   ///< the binary body
    bool swap_ = false;                 ///< the body's byte order is not this machine's
    const Element* element_ = nullptr;  ///< being read, for messages (none: the header)
    std::size_t index_ = 0;             ///< of the element being read
};

}  // namespace

void readPly(const std::filesystem::path& file, MeshDesc& mesh) {
    PlyReader(file).read(mesh);
}

}  // namespace lamina::render
