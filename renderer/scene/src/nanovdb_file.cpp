// NanoVDB grid files (volume_files.h), read with Debian's header-only libnanovdb-dev.
//
// NanoVDB's own readers trust a file: its sizes decide allocations and its node offsets are
// followed without checks. This reader parses the segment header and grid metadata itself,
// checks every size against the file's length and the grid limits before allocating, and walks
// the tree (root tiles, upper, lower and leaf nodes) checking that every node lies inside the
// grid's buffer and sits where its parent's slot says, so a hostile or truncated file is one
// InputError line, never a crash or an unbounded loop.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/core/json_reader.h"
#include "lamina/scene/grid_file.h"
#include "lamina/scene/volume_files.h"

#ifdef LAMINA_HAS_NANOVDB
#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/IO.h>
#endif

namespace lamina::render {

namespace {

/// NanoVDB's magic number, "NanoVDB0" read as a little-endian uint64.
constexpr std::uint64_t kNanoVdbMagic = 0x304244566f6e614eull;
/// The largest .nvdb file read (a dense grid of kMaxGridValues floats is 256 MiB; a sparse
/// file holding such a region with its other grids stays well under this).
constexpr std::uintmax_t kMaxNanoVdbBytes = std::uintmax_t(4) << 30;

}  // namespace

bool isNanoVdbFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char b[8];
    if (!in.read(reinterpret_cast<char*>(b), 8)) return false;
    std::uint64_t magic = 0;
    for (int i = 7; i >= 0; --i)
        magic = magic << 8 | b[i];
    return magic == kNanoVdbMagic;
}

#ifndef LAMINA_HAS_NANOVDB

bool readsNanoVdb() {
    return false;
}

NanoVdbGrid readNanoVdbFile(const std::filesystem::path& path, const std::string&) {
    throw InputError(path.string() +
                     ": this build of lamina does not read NanoVDB files (libnanovdb-dev was "
                     "not found when it was built; scripts/setup.sh installs it)");
}

#else

bool readsNanoVdb() {
    return true;
}

namespace {

using FloatGrid = nanovdb::NanoGrid<float>;
using Root = nanovdb::NanoRoot<float>;
using Upper = nanovdb::NanoUpper<float>;
using Lower = nanovdb::NanoLower<float>;
using Leaf = nanovdb::NanoLeaf<float>;

/// The dense grid being filled: the index box [lo, hi] (inclusive) and its values.
struct Dense {
    nanovdb::Coord lo, hi;
    int nx, ny, nz;
    std::vector<float> values;
    std::string file;

    /// Writes `v` over the cube of `size` voxels at `origin` where it meets the box.
    void fill(const nanovdb::Coord& origin, int size, float v) {
        const int x0 = std::max(origin[0], lo[0]), x1 = std::min(origin[0] + size - 1, hi[0]);
        const int y0 = std::max(origin[1], lo[1]), y1 = std::min(origin[1] + size - 1, hi[1]);
        const int z0 = std::max(origin[2], lo[2]), z1 = std::min(origin[2] + size - 1, hi[2]);
        if (x0 > x1 || y0 > y1 || z0 > z1) return;
        check(v, origin);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    values[index(x, y, z)] = v;
    }
    bool meets(const nanovdb::Coord& origin, int size) const {
        for (int a = 0; a < 3; ++a)
            if (origin[a] + std::int64_t(size) - 1 < lo[a] || origin[a] > hi[a]) return false;
        return true;
    }
    std::size_t index(int x, int y, int z) const {
        // One cell of background around the box: the densified grid starts at lo - 1.
        return (std::size_t(z - lo[2] + 1) * std::size_t(ny) + std::size_t(y - lo[1] + 1)) *
                   std::size_t(nx) +
               std::size_t(x - lo[0] + 1);
    }
    void check(float v, const nanovdb::Coord& at) const {
        if (!(v >= 0.0f) || !std::isfinite(v))
            throw InputError(file + ": the value at (" + std::to_string(at[0]) + ", " +
                             std::to_string(at[1]) + ", " + std::to_string(at[2]) + ") is " +
                             (std::isnan(v) ? std::string("NaN") : formatNumber(double(v))) +
                             ": expected a finite density >= 0");
    }
};

/// The grid's buffer and the checks of a node's place in it.
struct Buffer {
    const char* begin;
    std::size_t size;
    std::string file;

    template <typename Node>
    const Node* node(const void* p, const char* what) const {
        const char* c = static_cast<const char*>(p);
        if (c < begin || c > begin + size || std::size_t(begin + size - c) < sizeof(Node) ||
            (c - begin) % NANOVDB_DATA_ALIGNMENT != 0)
            throw InputError(file + ": a " + what + " node lies outside the grid's data " +
                             "(a damaged or truncated file)");
        return reinterpret_cast<const Node*>(c);
    }
};

[[noreturn]] void misplaced(const std::string& file, const char* what) {
    throw InputError(file + ": a " + what +
                     " node is not where its parent puts it (a damaged file)");
}

template <typename Node>
const Node* childAt(const Buffer& b, const void* parent, std::int64_t offset, const char* what) {
    // Offsets beyond the buffer are refused before the pointer is formed.
    const std::int64_t from = static_cast<const char*>(parent) - b.begin;
    if (offset <= -from || offset >= std::int64_t(b.size) - from) misplaced(b.file, what);
    return b.node<Node>(b.begin + (from + offset), what);
}

void readLeaf(const Leaf& leaf, Dense& d) {
    const nanovdb::Coord o = leaf.origin();
    for (std::uint32_t n = 0; n < Leaf::SIZE; ++n) {
        const nanovdb::Coord c = leaf.offsetToGlobalCoord(n);
        if (c[0] < d.lo[0] || c[0] > d.hi[0] || c[1] < d.lo[1] || c[1] > d.hi[1] ||
            c[2] < d.lo[2] || c[2] > d.hi[2])
            continue;
        const float v = leaf.getValue(n);
        d.check(v, c);
        d.values[d.index(c[0], c[1], c[2])] = v;
    }
    (void)o;
}

template <typename Node, typename Child, typename ReadChild>
void readInternal(const Buffer& b, const Node& node, const nanovdb::Coord& expected, Dense& d,
                  const char* what, const char* childWhat, ReadChild&& readChild) {
    if (node.origin() != expected) misplaced(b.file, what);
    const auto* data = node.data();
    for (std::uint32_t n = 0; n < Node::SIZE; ++n) {
        const nanovdb::Coord origin = node.offsetToGlobalCoord(n);
        if (!d.meets(origin, int(Child::DIM))) continue;
        if (data->mChildMask.isOn(n))
            readChild(*childAt<Child>(b, data, data->mTable[n].child, childWhat), origin);
        else
            d.fill(origin, int(Child::DIM), data->mTable[n].value);
    }
}

}  // namespace

NanoVdbGrid readNanoVdbFile(const std::filesystem::path& path, const std::string& name) {
    const std::string file = path.string();
    const std::uintmax_t bytes = checkInputFile(path, kMaxNanoVdbBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(file + ": cannot be opened");
    std::uintmax_t at = 0;  // the position in the file
    const auto read = [&](void* to, std::uintmax_t n, const char* what) {
        if (n > bytes - at || !in.read(static_cast<char*>(to), std::streamsize(n)))
            throw InputError(file + ": the file ends in " + what + " (a truncated NanoVDB file)");
        at += n;
    };
    while (at < bytes) {
        nanovdb::io::Header header;
        static_assert(sizeof(header) == 16);
        read(&header, sizeof(header), "a segment header");
        if (header.magic != kNanoVdbMagic)
            throw InputError(file + ": expected a NanoVDB segment (its magic number)");
        if (header.version.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER)
            throw InputError(file + ": NanoVDB file format " +
                             std::to_string(header.version.getMajor()) + ".x; this build reads " +
                             std::to_string(NANOVDB_MAJOR_VERSION_NUMBER) +
                             ".x (convert it with NanoVDB's tools of that version)");
        if (header.codec != nanovdb::io::Codec::NONE)
            throw InputError(file +
                             ": the grids are compressed (zip or blosc); lamina reads "
                             "uncompressed NanoVDB files (convert it with nanovdb_convert)");
        std::vector<nanovdb::io::MetaData> metas(header.gridCount);
        std::vector<std::string> names(header.gridCount);
        for (std::size_t i = 0; i < metas.size(); ++i) {
            read(&metas[i], sizeof(nanovdb::io::MetaData), "a grid's description");
            if (metas[i].nameSize > 4096)
                throw InputError(file + ": a grid name of " + std::to_string(metas[i].nameSize) +
                                 " bytes; at most 4096 are read");
            names[i].resize(metas[i].nameSize);
            read(names[i].data(), metas[i].nameSize, "a grid's name");
            names[i] = names[i].c_str();  // up to its terminating 0
        }
        for (std::size_t i = 0; i < metas.size(); ++i) {
            const nanovdb::io::MetaData& m = metas[i];
            if (m.fileSize > bytes - at)
                throw InputError(file + ": grid \"" + names[i] + "\" has " +
                                 std::to_string(m.fileSize) + " bytes, past the file's end");
            if (names[i] != name) {
                in.seekg(std::streamoff(m.fileSize), std::ios::cur);
                at += m.fileSize;
                continue;
            }
            if (m.gridType != nanovdb::GridType::Float)
                throw InputError(file + ": grid \"" + name + "\" is not a float grid");
            if (m.gridSize != m.fileSize || m.fileSize < sizeof(nanovdb::GridData) +
                                                             sizeof(nanovdb::TreeData<3>) +
                                                             sizeof(Root))
                throw InputError(file + ": grid \"" + name + "\" has an inconsistent size");
            // NanoVDB's nodes want 32-byte alignment: a buffer of 32-byte blocks.
            std::vector<nanovdb::Vec4d> storage((m.fileSize + 31) / 32);
            read(storage.data(), m.fileSize, "a grid's data");
            const Buffer b{reinterpret_cast<const char*>(storage.data()), std::size_t(m.fileSize),
                           file};
            const FloatGrid& grid = *b.node<FloatGrid>(b.begin, "grid");
            if (grid.data()->mMagic != NANOVDB_MAGIC_NUMBER ||
                grid.gridType() != nanovdb::GridType::Float || grid.gridSize() != m.fileSize)
                throw InputError(file + ": grid \"" + name + "\" has a damaged header");
            const auto& tree = grid.tree();
            const Root& root =
                *childAt<Root>(b, &tree, std::int64_t(tree.data()->mNodeOffset[3]), "root");
            const std::uint32_t tiles = root.tileCount();
            if (std::uint64_t(tiles) * sizeof(Root::Tile) >
                b.size - std::size_t(reinterpret_cast<const char*>(&root) - b.begin) - sizeof(Root))
                throw InputError(file + ": the root node's tiles lie outside the grid's data");
            const nanovdb::CoordBBox box = grid.indexBBox();
            NanoVdbGrid out;
            Dense d{box.min(), box.max(), 0, 0, 0, {}, file};
            std::int64_t n[3];
            for (int a = 0; a < 3; ++a) {
                n[a] = std::int64_t(box.max()[a]) - box.min()[a] + 3;  // with the ring
                if (n[a] < 3 || n[a] > kMaxGridAxis)
                    throw InputError(file + ": grid \"" + name + "\" has " +
                                     (n[a] < 3 ? std::string("no active voxels")
                                               : std::to_string(n[a]) +
                                                     " voxels along an axis; at "
                                                     "most " +
                                                     std::to_string(kMaxGridAxis) + " are read"));
            }
            if (std::uint64_t(n[0] * n[1] * n[2]) > kMaxGridValues)
                throw InputError(file + ": grid \"" + name + "\" spans " +
                                 std::to_string(n[0] * n[1] * n[2]) + " voxels; at most " +
                                 std::to_string(kMaxGridValues) + " are read");
            d.nx = int(n[0]);
            d.ny = int(n[1]);
            d.nz = int(n[2]);
            const float background = root.background();
            d.check(background, box.min());
            d.values.assign(std::size_t(n[0] * n[1] * n[2]), background);
            const auto* rootData = root.data();
            for (std::uint32_t t = 0; t < tiles; ++t) {
                const Root::Tile& tile = *rootData->tile(t);
                const nanovdb::Coord origin = tile.origin();
                if (!d.meets(origin, int(Upper::DIM))) continue;
                if (!tile.isChild()) {
                    d.fill(origin, int(Upper::DIM), tile.value);
                    continue;
                }
                const Upper& upper = *childAt<Upper>(b, rootData, tile.child, "upper");
                readInternal<Upper, Lower>(b, upper, origin, d, "upper", "lower",
                                           [&](const Lower& lower, const nanovdb::Coord& o) {
                                               readInternal<Lower, Leaf>(
                                                   b, lower, o, d, "lower", "leaf",
                                                   [&](const Leaf& leaf, const nanovdb::Coord& lo) {
                                                       if (leaf.origin() != lo)
                                                           misplaced(file, "leaf");
                                                       readLeaf(leaf, d);
                                                   });
                                           });
            }
            out.grid.nx = d.nx;
            out.grid.ny = d.ny;
            out.grid.nz = d.nz;
            out.grid.values = std::move(d.values);
            // Voxel i's value sits at index coordinate i: the densified cells' centres at
            // lo - 1 ... hi + 1 span [lo - 1.5, hi + 1.5].
            for (int a = 0; a < 3; ++a) {
                out.indexMin[a] = double(box.min()[a]) - 1.5;
                out.indexMax[a] = double(box.max()[a]) + 1.5;
            }
            const nanovdb::Map& map = grid.map();
            for (int r = 0; r < 3; ++r) {
                for (int c = 0; c < 3; ++c)
                    out.indexToWorld[c][r] = map.mMatD[r * 3 + c];
                out.indexToWorld[3][r] = map.mVecD[r];
            }
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c)
                    if (!std::isfinite(out.indexToWorld[c][r]))
                        throw InputError(file + ": grid \"" + name + "\" has a non-finite map");
            if (std::abs(glm::determinant(out.indexToWorld)) < 1e-300)
                throw InputError(file + ": grid \"" + name + "\" has a singular map");
            return out;
        }
    }
    throw InputError(file + ": no grid named \"" + name + "\"");
}

#endif

}  // namespace lamina::render
