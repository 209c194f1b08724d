// Grid media (docs/media.md, "Grid media"): the density grid inline and in a lamina grid file,
// one clean error line for every bad grid (hostile sizes cost no memory), trilinear
// interpolation with clamped edges, and the majorant grid's conservativeness, checked against
// the density everywhere along random rays through the majorant walk the trackers use.
// Broken once on purpose: majorants 20% too small fail MajorantsBoundEveryDensityAlongRays (and
// MajorantsAreConservative); without the one value of margin around a cell's support both still
// pass (rounding at the faces is rarer than the samples), which is why the margin is there
// against a failure the sampling cannot show.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "lamina/core/json_reader.h"
#include "lamina/integrators/majorant_walk.h"
#include "lamina/scene/grid_file.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using testing::errorOf;

std::string gridFile(const std::string& header, const std::vector<float>& values) {
    std::string bytes = header + "\n";
    bytes.resize(bytes.size() + 4 * values.size());
    std::memcpy(bytes.data() + header.size() + 1, values.data(), 4 * values.size());
    return bytes;
}

class GridFile : public testing::ScratchDirectoryTest {};

TEST_F(GridFile, ReadsTheValuesInOrder) {
    const auto p = write(
        "g.lgrid", gridFile(R"({"lamina_grid": 1, "size": [2, 3, 1]})", {0, 1, 2, 3, 4, 5.5f}));
    const DensityGrid g = readGridFile(p);
    EXPECT_EQ(g.nx, 2);
    EXPECT_EQ(g.ny, 3);
    EXPECT_EQ(g.nz, 1);
    EXPECT_EQ(g.at(1, 2, 0), 5.5f);  // x fastest
    EXPECT_EQ(g.at(0, 1, 0), 2.0f);
}

TEST_F(GridFile, RefusesBadFilesInOneLine) {
    const auto line = [](const std::string& m) { return m.find('\n') == std::string::npos; };
    const std::string h = R"({"lamina_grid": 1, "size": [2, 2, 2]})";
    const std::vector<float> eight(8, 1.0f);
    std::vector<float> nan = eight, negative = eight;
    nan[5] = std::numeric_limits<float>::quiet_NaN();
    negative[3] = -1.0f;
    const std::vector<std::pair<std::string, std::string>> cases = {
        // A huge header with a small file: refused by the length, before any allocation.
        {gridFile(R"({"lamina_grid": 1, "size": [65536, 65536, 65536]})", eight),
         "size: has 281474976710656 values; at most 67108864"},
        {gridFile(R"({"lamina_grid": 1, "size": [4000, 4000, 4]})", eight),
         "expected 256000000 bytes of float32"},
        {gridFile(h, std::vector<float>(7, 1.0f)), "expected 32 bytes of float32"},
        {gridFile(h, std::vector<float>(9, 1.0f)), "expected 32 bytes of float32"},
        {gridFile(h, nan), "value 5 (x 1, y 0, z 1) is NaN: expected a finite density >= 0"},
        {gridFile(h, negative), "value 3 (x 1, y 1, z 0) is -1"},
        {gridFile(R"({"lamina_grid": 1, "size": [2, 0, 2]})", eight),
         "size: expected [nx, ny, nz]"},
        {gridFile(R"({"lamina_grid": 1, "size": [2, 2.5, 2]})", eight), "size: expected"},
        {gridFile(R"({"lamina_grid": 2, "size": [2, 2, 2]})", eight), "lamina_grid"},
        {gridFile(R"({"size": [2, 2, 2]})", eight), "lamina_grid: missing"},
        {gridFile(R"({"lamina_grid": 1, "size": [2, 2, 2], "scale": 2})", eight), "scale"},
        {gridFile(R"({"lamina_grid": 1, "size": [2, 2, 2])", eight), "g.lgrid"},
        {std::string(5000, ' '), "a first line of at most 4096 bytes"},
        {"", "a first line"},
    };
    for (const auto& [bytes, expected] : cases) {
        const auto p = write("g.lgrid", bytes);
        const std::string m = errorOf([&] { readGridFile(p); });
        EXPECT_NE(m.find(expected), std::string::npos) << m;
        EXPECT_TRUE(line(m)) << m;
        EXPECT_EQ(m.rfind(p.string(), 0), 0u) << m;  // names the file first
    }
}

TEST_F(GridFile, IsNamedByAGridMediumRelativeToTheScene) {
    write("cloud.lgrid", gridFile(R"({"lamina_grid": 1, "size": [1, 1, 2]})", {0.25f, 2.0f}));
    const auto scene = write("scene.json", R"({
      "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "media": {"cloud": {"type": "grid", "density": "cloud.lgrid", "sigma_s": 2, "scale": 0.5,
                          "bounds": {"min": [-1, -2, -3], "max": [1, 2, 3]}}},
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "sphere", "material": "interface", "interior": "cloud"},
                 {"type": "rectangle", "material": "m", "emission": {"radiance": 1},
                  "transform": [{"translate": [0, 0, 5]}]}]})");
    const SceneDesc s = loadScene(scene.string());
    ASSERT_EQ(s.media.size(), 1u);
    const MediumDesc& m = s.media[0];
    EXPECT_EQ(m.kind, MediumKind::Grid);
    ASSERT_TRUE(m.grid);
    EXPECT_DOUBLE_EQ(m.sigmaS[0], 1.0);  // sigma_s times scale, per unit density
    EXPECT_EQ(m.grid->boxMin, Vec3f(-1, -2, -3));
    EXPECT_EQ(m.grid->boxMax, Vec3f(1, 2, 3));
    // The two values at the centres of the halves of z, clamped beyond them.
    EXPECT_FLOAT_EQ(m.grid->densityAt(Vec3f(0, 0, -1.5f)), 0.25f);
    EXPECT_FLOAT_EQ(m.grid->densityAt(Vec3f(0, 0, -2.9f)), 0.25f);
    EXPECT_FLOAT_EQ(m.grid->densityAt(Vec3f(0, 0, 0)), 0.5f * (0.25f + 2.0f));
    EXPECT_FLOAT_EQ(m.grid->densityAt(Vec3f(0, 0, 2.9f)), 2.0f);
}

std::string gridScene(const std::string& medium) {
    return R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "media": {"g": )" +
           medium + R"(},
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "sphere", "material": "interface", "interior": "g"},
                 {"type": "rectangle", "material": "m", "emission": {"radiance": 1},
                  "transform": [{"translate": [0, 0, 5]}]}]})";
}

TEST(GridMediumReader, ReadsAnInlineGridAndDefaultsToTheUnitCube) {
    const SceneDesc s = testing::sceneFromText(gridScene(
        R"({"type": "grid", "sigma_a": [1, 2, 3], "density": {"size": [2, 1, 1], "values": [1, 3]}})"));
    const GridDensity& g = *s.media[0].grid;
    EXPECT_EQ(g.boxMin, Vec3f(0.0f));
    EXPECT_EQ(g.boxMax, Vec3f(1.0f));
    EXPECT_FLOAT_EQ(g.densityAt(Vec3f(0.5f, 0.5f, 0.5f)), 2.0f);
    EXPECT_FLOAT_EQ(g.densityAt(Vec3f(0.375f, 0.1f, 0.9f)), 1.5f);
}

TEST(GridMediumReader, RefusesBadGridsWithTheJsonPath) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"type": "grid"})", "media.g.density: missing"},
        {R"({"type": "grid", "density": {"size": [2, 1, 1], "values": [1]}})",
         "media.g.density.values: expected an array of 2 densities"},
        {R"({"type": "grid", "density": {"size": [2, 1, 1], "values": [1, -2]}})",
         "media.g.density.values[1]"},
        {R"({"type": "grid", "density": {"size": [2, 1], "values": [1, 2]}})",
         "media.g.density.size: expected [nx, ny, nz]"},
        {R"({"type": "grid", "density": {"size": [1, 1, 1], "values": [1]},
             "bounds": {"min": [0, 0, 0], "max": [1, 0, 1]}})",
         "media.g.bounds.max: expected every coordinate greater than min's"},
        {R"({"type": "grid", "density": {"size": [1, 1, 1], "values": [1e30]}, "sigma_s": 1e20})",
         "media.g.density: the largest density 1"},
        {R"({"type": "grid", "density": "missing.lgrid"})", "missing.lgrid"},
        {R"({"type": "homogeneous", "density": {"size": [1, 1, 1], "values": [1]}})", "density"},
    };
    for (const auto& [medium, expected] : cases) {
        const std::string m = errorOf([&] { testing::sceneFromText(gridScene(medium)); });
        EXPECT_NE(m.find(expected), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

/// A grid of random densities (some zero, some high) of `n` values.
DensityGrid randomGrid(int nx, int ny, int nz, std::mt19937& rng) {
    DensityGrid g;
    g.nx = nx;
    g.ny = ny;
    g.nz = nz;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < nx * ny * nz; ++i) {
        const float v = u(rng);
        g.values.push_back(v < 0.3f ? 0.0f : v < 0.9f ? v : 20.0f * v);
    }
    return g;
}

// Every trilinear lookup inside a coarse cell is at most the cell's maximum: lookups at random
// points of every cell, for coarse grids finer, equal to and coarser than the grid.
TEST(MajorantGrid, MajorantsAreConservative) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const auto& [nx, ny, nz] : {std::array{13, 7, 5}, std::array{40, 33, 17}}) {
        const DensityGrid g = randomGrid(nx, ny, nz, rng);
        for (int resolution : {3, 16, 64}) {
            const MajorantGrid m = MajorantGrid::build(g, resolution);
            EXPECT_EQ(m.nx, std::min(resolution, nx));
            for (int cz = 0; cz < m.nz; ++cz)
                for (int cy = 0; cy < m.ny; ++cy)
                    for (int cx = 0; cx < m.nx; ++cx)
                        for (int k = 0; k < 20; ++k) {
                            const Vec3f p((float(cx) + u(rng)) / float(m.nx),
                                          (float(cy) + u(rng)) / float(m.ny),
                                          (float(cz) + u(rng)) / float(m.nz));
                            ASSERT_LE(g.lookup(p), m.at(cx, cy, cz))
                                << "cell " << cx << " " << cy << " " << cz << " resolution "
                                << resolution;
                        }
        }
    }
}

// The majorant walk covers a ray's part inside the box with consecutive pieces, and every
// density on a piece is at most the piece's maximum (what delta and ratio tracking assume).
TEST(MajorantGrid, MajorantsBoundEveryDensityAlongRays) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    GridDensity grid;
    grid.boxMin = Vec3f(-1.0f, 0.5f, -2.0f);
    grid.boxMax = Vec3f(2.0f, 1.5f, 3.0f);
    grid.density = randomGrid(37, 11, 23, rng);
    grid.majorants = MajorantGrid::build(grid.density);
    int pieces = 0;
    for (int ray = 0; ray < 2000; ++ray) {
        const Vec3f o(-3.0f + 8.0f * u(rng), -1.0f + 3.0f * u(rng), -4.0f + 9.0f * u(rng));
        // Some rays along an axis (zero direction components).
        Vec3f d(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        if (ray % 7 == 0) d = Vec3f(0.0f, 0.0f, ray % 2 ? 1.0f : -1.0f);
        d = glm::normalize(d);
        const float tMax = ray % 3 ? std::numeric_limits<float>::infinity() : 4.0f * u(rng);
        float last = -1.0f;
        walkMajorants(grid, o, d, tMax, [&](float t0, float t1, float maximum) {
            EXPECT_LT(t0, t1);
            EXPECT_LE(t1, tMax);
            if (last >= 0.0f) {
                EXPECT_NEAR(t0, last, 1e-4f);  // consecutive pieces
            }
            last = t1;
            ++pieces;
            for (int k = 0; k < 8; ++k) {
                const float t = t0 + (t1 - t0) * u(rng);
                EXPECT_LE(grid.densityAt(o + d * t), maximum) << "ray " << ray << " t " << t;
            }
            return true;
        });
    }
    EXPECT_GT(pieces, 2000);
}

}  // namespace
}  // namespace lamina::render
