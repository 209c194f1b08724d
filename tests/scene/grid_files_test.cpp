// Grid files of other renderers (volume_files.h) and per-cell colour grids (colour_grid.h):
// - a Mitsuba .vol (1 and 3 channels) and a NanoVDB file made here with NanoVDB's own
//   header-only builder read back value-exact at chosen voxels, and a voxel's centre placed in
//   the scene where the file (NanoVDB's map) and the medium's transform put it;
// - hostile files (truncations, bad magic, sizes beyond the limits or the file, NaN,
//   negative values, damaged node offsets) refused with one InputError line, never a crash;
// - a colour grid's spectral lookup at a cell centre is the cell's unbounded spectrum
//   (RgbSpectrum), its bound is above its values at every wavelength, and between centres
//   the RGB lookup is trilinear.
// Broken once on purpose each: the .vol channel index taken as the fastest index in a 3-channel
// volume (values swapped: ThreeChannelVolumeReadsBack fails), NanoVDB's box without the half-voxel
// shift (index min - 1 instead of - 1.5: the voxel centre lands half a voxel off and
// NanoVdbGridReadsBackAndPlacesItsVoxels fails), the node range check in nanovdb_file.cpp removed
// (DamagedNanoVdbFilesAreRefused crashes with a segmentation fault on a damaged offset), and the
// spectral bound without the vertex of the quadratic (BoundsAreAboveEveryWavelength fails for a
// green cell, whose spectrum peaks inside the range).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <random>

#include "lamina/core/error.h"
#include "lamina/scene/colour_grid.h"
#include "lamina/scene/volume_files.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "render_helpers.h"
#include "scratch_directory.h"

#ifdef LAMINA_HAS_NANOVDB
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>
#endif

namespace lamina::render {
namespace {

using testing::errorOf;

std::string int32(std::int32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i)
        s[std::size_t(i)] = char((std::uint32_t(v) >> (8 * i)) & 0xff);
    return s;
}
std::string float32(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    return int32(std::int32_t(b));
}

/// A Mitsuba volume: 'V' 'O' 'L' 3, encoding 1, the resolution, the channels, a box, the values.
std::string volFile(int nx, int ny, int nz, int channels, const std::vector<float>& values) {
    std::string s = "VOL";
    s += char(3);
    s += int32(1) + int32(nx) + int32(ny) + int32(nz) + int32(channels);
    for (const float b : {-1.0f, -2.0f, -3.0f, 1.0f, 2.0f, 3.0f})
        s += float32(b);
    for (const float v : values)
        s += float32(v);
    return s;
}

class GridFiles : public testing::ScratchDirectoryTest {};

TEST_F(GridFiles, OneChannelVolumeReadsBack) {
    std::vector<float> v(3 * 4 * 5);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = 0.25f * float(i);
    const auto p = write("a.vol", volFile(3, 4, 5, 1, v));
    ASSERT_TRUE(isMitsubaVolume(p));
    const MitsubaVolume m = readMitsubaVolume(p);
    EXPECT_EQ(m.grid.nx, 3);
    EXPECT_EQ(m.grid.ny, 4);
    EXPECT_EQ(m.grid.nz, 5);
    EXPECT_EQ(m.grid.channels, 1);
    // data[((z yres + y) xres + x)]: voxel (2, 1, 3) is value 2 + 3 (1 + 4 * 3) = 41.
    EXPECT_EQ(m.grid.at(2, 1, 3), 0.25f * 41.0f);
    EXPECT_EQ(m.grid.at(0, 0, 0), 0.0f);
    EXPECT_EQ(m.boxMin, Vec3f(-1, -2, -3));
    EXPECT_EQ(m.boxMax, Vec3f(1, 2, 3));
}

TEST_F(GridFiles, ThreeChannelVolumeReadsBack) {
    std::vector<float> v;
    for (int cell = 0; cell < 8; ++cell)
        for (int c = 0; c < 3; ++c)
            v.push_back(float(10 * cell + c));
    const MitsubaVolume m = readMitsubaVolume(write("c.vol", volFile(2, 2, 2, 3, v)));
    ASSERT_EQ(m.grid.channels, 3);
    // Cell (1, 0, 1) is cell 5; its channels follow each other.
    const ColourGrid g = ColourGrid::fromGrid(m.grid, Rgb<double>(1.0, 2.0, 0.5));
    EXPECT_EQ(g.rgb[5], Rgb<float>(50.0f, 102.0f, 26.0f));
    EXPECT_EQ(g.lookupRgb(Vec3f(0.75f, 0.25f, 0.75f)), Rgb<float>(50.0f, 102.0f, 26.0f));
}

TEST_F(GridFiles, HostileVolumesAreRefused) {
    const std::string good = volFile(2, 2, 2, 1, std::vector<float>(8, 1.0f));
    // Every truncation of a good file.
    for (std::size_t n = 0; n < good.size(); ++n) {
        const auto p = write("t.vol", good.substr(0, n));
        EXPECT_NE(errorOf([&] { readMitsubaVolume(p); }), "(accepted)") << n << " bytes";
    }
    const auto refused = [&](const std::string& bytes, const std::string& expected) {
        const auto p = write("h.vol", bytes);
        const std::string e = errorOf([&] { readMitsubaVolume(p); });
        EXPECT_NE(e.find(expected), std::string::npos) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
    };
    std::string version = good;
    version[3] = char(2);
    refused(version, "version 3");
    std::string encoding = good;
    encoding.replace(4, 4, int32(2));
    refused(encoding, "encoding 2");
    // A header of 65536^3 cells over a file of 80 bytes: refused before any allocation.
    refused(volFile(65536, 65536, 65536, 1, {1, 2, 3, 4, 5, 6, 7, 8}), "cells; at most");
    refused(volFile(-1, 2, 2, 1, {}), "resolution -1");
    refused(volFile(2, 2, 2, 6, {}), "6 channels");
    refused(good + "x", "after the header, got 33");
    refused(volFile(2, 2, 2, 1, {1, 1, 1, 1, 1, std::nanf(""), 1, 1}), "NaN");
    refused(volFile(2, 2, 2, 1, {1, 1, 1, 1, 1, 1, -2, 1}), "(x 0, y 1, z 1, channel 0) is -2");
}

TEST(ColourGrids, SpectralLookupIsTheCellsUnboundedSpectrum) {
    DensityGrid g;
    g.nx = 2;
    g.channels = 3;
    g.values = {0.2f, 0.9f, 0.1f, 3.0f, 1.0f, 0.5f};
    const ColourGrid c = ColourGrid::fromGrid(g, Rgb<double>(1.0));
    for (const float nm : {400.0f, 480.0f, 550.0f, 610.0f, 700.0f}) {
        float out = 0;
        // The first cell's centre (x = 1/4): its own spectrum alone.
        c.lookupSpectral(Vec3f(0.25f, 0.5f, 0.5f), &nm, 1, &out);
        const double expected =
            RgbSpectrum(Rgb<double>(0.2, 0.9, 0.1), RgbSpectrumKind::Unbounded)(nm);
        EXPECT_NEAR(out, expected, 1e-4 * expected + 1e-6) << nm << " nm";
        // Halfway between the centres: the average of the two spectra.
        c.lookupSpectral(Vec3f(0.5f, 0.5f, 0.5f), &nm, 1, &out);
        const double other =
            RgbSpectrum(Rgb<double>(3.0, 1.0, 0.5), RgbSpectrumKind::Unbounded)(nm);
        EXPECT_NEAR(out, 0.5 * (expected + other), 1e-4 * other) << nm << " nm";
    }
    const Rgb<float> mid = c.lookupRgb(Vec3f(0.5f, 0.1f, 0.9f));
    EXPECT_NEAR(mid[0], 1.6f, 1e-6f);
    EXPECT_NEAR(mid[1], 0.95f, 1e-6f);
    EXPECT_NEAR(mid[2], 0.3f, 1e-6f);
}

TEST(ColourGrids, BoundsAreAboveEveryWavelength) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    DensityGrid g;
    g.nx = 64;
    g.channels = 3;
    for (int i = 0; i < 64 * 3; ++i)
        g.values.push_back(u(rng));
    g.values[0] = 0.05f;  // a saturated green cell, whose spectrum peaks inside 360-830 nm
    g.values[1] = 2.0f;
    g.values[2] = 0.05f;
    const ColourGrid c = ColourGrid::fromGrid(g, Rgb<double>(1.0));
    for (int cell = 0; cell < 64; ++cell) {
        const Vec3f at((float(cell) + 0.5f) / 64.0f, 0.5f, 0.5f);
        for (int k = 0; k <= 470; ++k) {
            const float nm = 360.0f + float(k);
            float v = 0;
            c.lookupSpectral(at, &nm, 1, &v);
            ASSERT_LE(v, c.bound(std::size_t(cell))) << "cell " << cell << " at " << nm << " nm";
        }
        EXPECT_LE(c.rgb[std::size_t(cell)].maxValue(), c.bound(std::size_t(cell)));
    }
}

#ifdef LAMINA_HAS_NANOVDB

/// A NanoVDB float grid "density" with voxel size 0.5 and origin (1, 2, 3): voxel (i, j, k)'s
/// centre is at (1 + i / 2, 2 + j / 2, 3 + k / 2). Values 1 + i + 10 j + 100 k over i in
/// [-2, 5], j in [0, 3], k in [7, 9] (a box across leaf nodes: i < 0). `childOffsetAt`
/// receives where in the file the root's first child tile keeps its node's offset.
std::filesystem::path writeNanoVdb(const std::filesystem::path& path,
                                   std::size_t* childOffsetAt = nullptr) {
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    auto acc = builder.getAccessor();
    for (int k = 7; k <= 9; ++k)
        for (int j = 0; j <= 3; ++j)
            for (int i = -2; i <= 5; ++i)
                acc.setValue(nanovdb::Coord(i, j, k), float(1 + i + 10 * j + 100 * k));
    auto handle = builder.getHandle<>(0.5, nanovdb::Vec3d(1, 2, 3), "density");
    nanovdb::io::writeGrid(path.string(), handle);
    if (childOffsetAt) {
        const auto* root = handle.grid<float>()->tree().root().data();
        const auto* tile = root->tile(0);
        for (std::uint32_t t = 0; !tile->isChild();)
            tile = root->tile(++t);
        // One grid: the file is its segment's headers, then the grid's buffer.
        *childOffsetAt = std::size_t(std::filesystem::file_size(path)) - handle.size() +
                         std::size_t(reinterpret_cast<const char*>(&tile->child) -
                                     reinterpret_cast<const char*>(handle.data()));
    }
    return path;
}

TEST_F(GridFiles, NanoVdbGridReadsBackAndPlacesItsVoxels) {
    const auto p = writeNanoVdb(dir_ / "smoke.nvdb");
    ASSERT_TRUE(isNanoVdbFile(p));
    ASSERT_TRUE(readsNanoVdb());
    const NanoVdbGrid g = readNanoVdbFile(p, "density");
    // The active box [-2, 5] x [0, 3] x [7, 9] with a ring of background: 10 x 6 x 5 cells.
    EXPECT_EQ(g.grid.nx, 10);
    EXPECT_EQ(g.grid.ny, 6);
    EXPECT_EQ(g.grid.nz, 5);
    EXPECT_EQ(g.grid.at(1 + 2 + 3, 1 + 2, 1 + 1), float(1 + 3 + 20 + 800));  // voxel (3, 2, 8)
    EXPECT_EQ(g.grid.at(0, 0, 0), 0.0f);                                     // the ring
    // In a scene: the medium's transform after the file's map. Voxel (3, 2, 8)'s centre is at
    // (2.5, 3, 7) in the file's space, (4.5, 3, 7) after the translation.
    const SceneDesc scene = testing::sceneFromText(
        R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
            "lights": [{"type": "point", "position": [0, 9, 0], "intensity": 1}],
            "media": {"smoke": {"type": "grid", "sigma_s": 1, "edges": "zero",
                                "density": ")" +
        p.string() + R"(", "transform": [{"translate": [2, 0, 0]}]}},
            "shapes": []})");
    const GridDensity& grid = *scene.media[0].grid;
    EXPECT_EQ(grid.densityAt(grid.pointToMedium(Vec3f(4.5f, 3.0f, 7.0f))), float(824));
    // Half a voxel towards +x: the average of voxels (3, 2, 8) and (4, 2, 8).
    EXPECT_NEAR(grid.densityAt(grid.pointToMedium(Vec3f(4.75f, 3.0f, 7.0f))), 824.5f, 1e-3f);
    // Beyond the last voxel (i = 5, at x = 5.5 in the scene) the density fades to the background.
    EXPECT_NEAR(grid.densityAt(grid.pointToMedium(Vec3f(5.75f, 3.0f, 7.0f))), 0.5f * 826.0f, 1e-3f);
    EXPECT_EQ(errorOf([&] { readNanoVdbFile(p, "temperature"); }),
              p.string() + ": no grid named \"temperature\"");
}

TEST_F(GridFiles, DamagedNanoVdbFilesAreRefused) {
    std::size_t childAt = 0;
    const auto p = writeNanoVdb(dir_ / "good.nvdb", &childAt);
    std::ifstream in(p, std::ios::binary);
    const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Every truncation within the headers and the root, then 200 lengths spread over the rest.
    std::vector<std::size_t> lengths;
    for (std::size_t n = 0; n < 1024; ++n)
        lengths.push_back(n);
    for (int k = 0; k < 200; ++k)
        lengths.push_back(1024 + (good.size() - 1025) * std::size_t(k) / 199);
    for (const std::size_t n : lengths) {
        const auto t = write("t.nvdb", good.substr(0, n));
        EXPECT_NE(errorOf([&] { readNanoVdbFile(t, "density"); }), "(accepted)") << n << " bytes";
    }
    // The root's child offset pointing far outside the file, back into the root, or off by 8:
    // each refused, never followed.
    for (const std::int64_t offset :
         {std::int64_t(1) << 40, std::int64_t(-64), std::int64_t(-1) << 40}) {
        std::string bad = good;
        std::memcpy(bad.data() + childAt, &offset, 8);
        const auto t = write("c.nvdb", bad);
        const std::string e = errorOf([&] { readNanoVdbFile(t, "density"); });
        EXPECT_NE(e.find("node"), std::string::npos) << offset << ": " << e;
    }
    std::string shifted = good;
    std::int64_t offset;
    std::memcpy(&offset, shifted.data() + childAt, 8);
    offset += 8;
    std::memcpy(shifted.data() + childAt, &offset, 8);
    EXPECT_NE(errorOf([&] { readNanoVdbFile(write("s.nvdb", shifted), "density"); }).find("node"),
              std::string::npos);
    // Random bytes of the headers, the grid's and tree's data and the root overwritten, 100
    // times at fixed seeds: accepted or one line, never a crash.
    std::mt19937 rng(5);
    int refusedCount = 0;
    for (int trial = 0; trial < 100; ++trial) {
        std::string bad = good;
        for (int k = 0; k < 4; ++k)
            bad[rng() % std::min<std::size_t>(bad.size(), childAt + 256)] = char(rng());
        const auto t = write("d.nvdb", bad);
        const std::string e = errorOf([&] { readNanoVdbFile(t, "density"); });
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        refusedCount += e != "(accepted)";
    }
    EXPECT_GT(refusedCount, 0);
    // A file of another renderer's magic, and an empty one.
    EXPECT_FALSE(isNanoVdbFile(write("e.nvdb", "")));
}

#endif

}  // namespace
}  // namespace lamina::render
