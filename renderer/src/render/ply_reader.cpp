#include "lamina/render/mesh_files.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>

#include "lamina/core/error.h"

namespace lamina::render {

namespace {

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
    std::string name;
    std::string type;       // scalar type, or the item type of a list
    std::string countType;  // list: the count's type; empty for scalars
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

std::size_t typeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

class PlyReader {
  public:
    explicit PlyReader(const std::filesystem::path& file)
        : file_(file), in_(file, std::ios::binary) {
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
                s >> e.name >> e.count;
                if (!s) fail("malformed element line: " + line);
                elements_.push_back(e);
            } else if (word == "property") {
                if (elements_.empty()) fail("property before any element");
                Property p;
                std::string t;
                s >> t;
                if (t == "list")
                    s >> p.countType >> p.type >> p.name;
                else {
                    p.type = t;
                    s >> p.name;
                }
                if (!s || typeSize(p.type) == 0 ||
                    (!p.countType.empty() && typeSize(p.countType) == 0))
                    fail("malformed or unsupported property line: " + line);
                elements_.back().properties.push_back(p);
            } else if (word == "end_header") {
                return;
            }
        }
        fail("no end_header");
    }

    double readScalar(const std::string& type) {
        if (format_ == Format::Ascii) {
            double v;
            if (!(in_ >> v)) fail("unexpected end of data or a non-number");
            return v;
        }
        unsigned char buf[8];
        const std::size_t n = typeSize(type);
        if (!in_.read(reinterpret_cast<char*>(buf), std::streamsize(n)))
            fail("unexpected end of data");
        const bool swap =
            (format_ == Format::BinaryBig) == (std::endian::native == std::endian::little);
        if (swap) std::reverse(buf, buf + n);
        auto as = [&](auto v) {
            std::memcpy(&v, buf, sizeof v);
            return double(v);
        };
        if (type == "char" || type == "int8") return as(std::int8_t{});
        if (type == "uchar" || type == "uint8") return as(std::uint8_t{});
        if (type == "short" || type == "int16") return as(std::int16_t{});
        if (type == "ushort" || type == "uint16") return as(std::uint16_t{});
        if (type == "int" || type == "int32") return as(std::int32_t{});
        if (type == "uint" || type == "uint32") return as(std::uint32_t{});
        if (type == "float" || type == "float32") return as(float{});
        return as(double{});
    }

    void read(MeshDesc& mesh) {
        readHeader();
        const std::uint32_t base = std::uint32_t(mesh.positions.size());
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
            for (std::size_t k = 0; k < e.count; ++k) {
                std::vector<std::uint32_t> polygon;
                for (std::size_t p = 0; p < e.properties.size(); ++p) {
                    const Property& prop = e.properties[p];
                    if (prop.countType.empty()) {
                        values[p] = readScalar(prop.type);
                        continue;
                    }
                    const double n = readScalar(prop.countType);
                    if (n < 0 || n > 1e6) fail("implausible list length in " + e.name);
                    for (int i = 0; i < int(n); ++i) {
                        const double v = readScalar(prop.type);
                        if (face && int(p) == list) {
                            if (v < 0) fail("negative vertex index in face " + std::to_string(k));
                            polygon.push_back(base + std::uint32_t(v));
                        }
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
        for (const auto& t : mesh.triangles)
            for (std::uint32_t i : t)
                if (i >= mesh.positions.size())
                    fail("face index " + std::to_string(i - base) + " is out of range (" +
                         std::to_string(mesh.positions.size() - base) + " vertices)");
        if (mesh.triangles.empty()) fail("no faces");
    }

  private:
    std::filesystem::path file_;
    std::ifstream in_;
    Format format_ = Format::Ascii;
    std::vector<Element> elements_;
};

}  // namespace

void readPly(const std::filesystem::path& file, MeshDesc& mesh) {
    PlyReader(file).read(mesh);
}

}  // namespace lamina::render
