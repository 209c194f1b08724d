#include "lamina/scene/rgl_bsdf_file.h"

#include <bit>
#include <cstring>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/measured.h"
#include "lamina/core/error.h"

namespace lamina::render {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the tensor file reader copies little-endian numbers as they are");

constexpr char kMagic[12] = "tensor_file";  // with its terminating zero: 12 bytes
constexpr std::uint8_t kUInt8 = 1, kFloat32 = 10, kFloat64 = 11;

// A field's name as a message shows it: bytes outside printable ASCII as \xNN, so that a
// hostile name cannot break the one-line error.
std::string printable(const std::string& name) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (const char c : name) {
        const auto b = static_cast<unsigned char>(c);
        if (b >= 0x20 && b < 0x7f) {
            out += c;
        } else {
            out += "\\x";
            out += kHex[b >> 4];
            out += kHex[b & 15];
        }
    }
    return out;
}

struct Field {
    std::uint8_t type = 0;
    std::uint64_t offset = 0;
    std::vector<std::uint64_t> shape;
    std::uint64_t count = 0;  ///< the product of the shape
};

// Reads the header of a tensor file held in `bytes`, checking every read against its length.
class TensorHeader {
  public:
    TensorHeader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {
        char magic[12];
        take(magic, sizeof magic, "the header");
        if (std::memcmp(magic, kMagic, sizeof magic) != 0)
            fail("expected a tensor file (an RGL .bsdf file): it starts with \"tensor_file\"");
        const auto major = read<std::uint8_t>("the version"),
                   minor = read<std::uint8_t>("the version");
        if (major != 1 || minor != 0)
            fail("expected a tensor file of version 1.0, got " + std::to_string(major) + "." +
                 std::to_string(minor));
        const auto fields = read<std::uint32_t>("the field count");
        for (std::uint32_t i = 0; i < fields; ++i) {
            const auto length = read<std::uint16_t>("a field's name");
            std::string raw(length, '\0');
            take(raw.data(), length, "a field's name");
            const std::string field = printable(raw);
            const auto rank = read<std::uint16_t>("field \"" + field + "\"");
            Field f;
            f.type = read<std::uint8_t>("field \"" + field + "\"");
            f.offset = read<std::uint64_t>("field \"" + field + "\"");
            if (f.type == 0 || f.type > kFloat64)
                fail("field \"" + field + "\": unknown type " + std::to_string(f.type));
            const std::uint64_t typeBytes = typeSize(f.type);
            // Every size is bounded by the file: the data must lie inside it.
            const std::uint64_t available =
                f.offset <= bytes_.size() ? bytes_.size() - f.offset : 0;
            f.count = 1;
            for (std::uint16_t k = 0; k < rank; ++k) {
                const auto size = read<std::uint64_t>("field \"" + field + "\"");
                if (size != 0 && f.count > available / typeBytes / size)
                    fail("field \"" + field + "\": its shape holds more data than the file");
                f.count *= size;
                f.shape.push_back(size);
            }
            if (f.offset > bytes_.size() || f.count * typeBytes > available)
                fail("field \"" + field + "\": its data lie beyond the end of the file");
            if (!fields_.emplace(raw, std::move(f)).second)
                fail("field \"" + field + "\" appears twice");
        }
    }

    bool has(const std::string& field) const { return fields_.count(field) != 0; }

    const Field& field(const std::string& name, std::uint8_t type) const {
        const auto it = fields_.find(name);
        if (it == fields_.end()) fail("the field \"" + name + "\" is missing");
        if (it->second.type != type)
            fail("field \"" + name + "\": expected " +
                 (type == kFloat32 ? std::string("float32") : std::string("uint8")) +
                 " values, got type " + std::to_string(it->second.type));
        return it->second;
    }

    MeasuredTensor floats(const std::string& name) const {
        const Field& f = field(name, kFloat32);
        MeasuredTensor t;
        t.shape.assign(f.shape.begin(), f.shape.end());
        t.values.resize(f.count);
        if (f.count)
            std::memcpy(t.values.data(), bytes_.data() + f.offset, f.count * sizeof(float));
        return t;
    }

    std::string bytes(const std::string& name) const {
        const Field& f = field(name, kUInt8);
        return bytes_.substr(f.offset, f.count);
    }

    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

  private:
    static std::uint64_t typeSize(std::uint8_t type) {
        static constexpr std::uint64_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 2, 4, 8};
        return sizes[type];
    }

    void take(void* out, std::size_t n, const std::string& what) {
        if (bytes_.size() - at_ < n) fail("the file ends inside " + what);
        std::memcpy(out, bytes_.data() + at_, n);
        at_ += n;
    }
    template <typename T>
    T read(const std::string& what) {
        T v;
        take(&v, sizeof v, what);
        return v;
    }

    const std::string& bytes_;
    std::string name_;
    std::size_t at_ = 0;
    std::map<std::string, Field> fields_;
};

}  // namespace

MeasuredBsdfTable readRglBsdfFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = readInputFile(path, kMaxRglFileBytes);
    const TensorHeader h(bytes, name);
    MeasuredBsdfFields f;
    f.description = h.bytes("description");
    const std::string jacobian = h.bytes("jacobian");
    if (jacobian.size() != 1) h.fail("field \"jacobian\": expected one value");
    f.jacobian = jacobian[0] != 0;
    f.thetaI = h.floats("theta_i");
    f.phiI = h.floats("phi_i");
    f.ndf = h.floats("ndf");
    f.sigma = h.floats("sigma");
    f.vndf = h.floats("vndf");
    f.luminance = h.floats("luminance");
    if (h.has("spectra")) {
        f.spectra = h.floats("spectra");
        f.wavelengths = h.floats("wavelengths");
    } else if (h.has("rgb")) {
        f.rgb = h.floats("rgb");
    } else {
        h.fail("expected the field \"spectra\" (with \"wavelengths\") or \"rgb\"");
    }
    try {
        return MeasuredBsdfTable(std::move(f));
    } catch (const std::invalid_argument& e) {
        h.fail(e.what());
    }
}

void loadMeasuredTables(const MaterialDesc& m) {
    if (const auto* measured = m.model.get<MeasuredMaterial>();
        measured && !measured->slot->table) {
        MeasuredTableSlot& slot = *measured->slot;
        // One table per file for as long as a material holds it (a scene may name a file many
        // times); the size and time tell a file rewritten in between from the one read.
        using Key = std::tuple<std::string, std::uintmax_t, std::filesystem::file_time_type>;
        static std::mutex mutex;
        static std::map<Key, std::weak_ptr<const MeasuredBsdfTable>> tables;
        std::error_code ec;
        const Key key{std::filesystem::weakly_canonical(slot.file, ec).string(),
                      std::filesystem::file_size(slot.file, ec),
                      std::filesystem::last_write_time(slot.file, ec)};
        const std::lock_guard lock(mutex);
        if (auto table = tables[key].lock()) {
            slot.table = std::move(table);
        } else {
            slot.table = std::make_shared<const MeasuredBsdfTable>(readRglBsdfFile(slot.file));
            tables[key] = slot.table;
        }
    }
    if (const MaterialKind* kind = findMaterialKind(m.type); kind && kind->nested)
        for (const MaterialDesc* inner : kind->nested(m.model))
            loadMeasuredTables(*inner);
}

}  // namespace lamina::render
