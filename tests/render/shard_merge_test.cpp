// Sample-range shards and crops (`render --samples`, `--crop`) and their merge (`lamina
// merge`): the merge of shards is the image one render of all their samples gives, up to the
// order of floating-point summation (relative 1e-6), for every integrator in every mode, with
// the polarised mode's Stokes layers and the spectral film's bins (`--spectral-film`); crops
// of the path integrator are the full render's pixels bit for bit; shards that do not belong
// together are refused, naming the files.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/output/render_metadata.h"
#include "lamina/output/shard_file.h"
#include "lamina/output/shard_merge.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using testing::errorOf;

constexpr int kSize = 20;

RenderOptions optionsFor(IntegratorKind integrator, RenderModeKind mode) {
    RenderOptions o;
    o.integrator = integrator;
    o.mode = mode;
    o.resolution = std::pair{kSize, kSize};
    o.maxDepth = 4;
    return o;
}

class Shards : public testing::ScratchDirectoryTest {
  protected:
    /// Renders a shard of `scene` into the scratch directory and returns its path.
    std::filesystem::path shard(const SceneDesc& scene, RenderOptions o, const std::string& name,
                                std::optional<SampleRange> samples,
                                std::optional<PixelBounds> crop = std::nullopt) {
        o.samples = samples;
        o.crop = crop;
        const RenderResult r = renderScene(scene, o);
        ImageMetadata meta = renderMetadata(scene, o, r, {"test", "test"});
        addShardMetadata(meta, scene, o, r);
        const std::filesystem::path path = dir_ / name;
        writeShardExr(path, *r.film, meta);
        return path;
    }
};

/// Relative difference, with an absolute floor for values near zero.
void expectClose(double got, double want, const std::string& what) {
    EXPECT_LE(std::abs(got - want), 1e-6 * std::abs(want) + 1e-12) << what;
}

TEST_F(Shards, EveryIntegratorAndModeMergesToTheSingleRender) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    for (const IntegratorKind integrator :
         {IntegratorKind::Path, IntegratorKind::Light, IntegratorKind::Bdpt})
        for (const RenderModeKind mode :
             {RenderModeKind::Rgb, RenderModeKind::Spectral, RenderModeKind::Polarised}) {
            const std::string label = std::string(kIntegratorNames.name(integrator)) + " " +
                                      std::string(kRenderModeNames.name(mode));
            RenderOptions o = optionsFor(integrator, mode);
            o.spp = 5;
            if (mode != RenderModeKind::Rgb) o.spectralBins = 6;
            const RenderResult full = renderScene(scene, o);
            o.spp.reset();
            // Samples 0:2 of the whole film, samples 2:3 in three crops tiling it.
            const std::vector<std::filesystem::path> paths = {
                shard(scene, o, "a.exr", SampleRange{0, 2}),
                shard(scene, o, "b.exr", SampleRange{2, 3}, PixelBounds{0, 7, 0, kSize}),
                shard(scene, o, "c.exr", SampleRange{2, 3}, PixelBounds{7, kSize, 0, 11}),
                shard(scene, o, "d.exr", SampleRange{2, 3}, PixelBounds{7, kSize, 11, kSize})};
            const MergedShards merged = mergeShards(paths);
            EXPECT_TRUE(merged.warnings.empty()) << label << ": " << merged.warnings.front();
            EXPECT_EQ(merged.metadata.strings.at("samples"), "0:5") << label;
            EXPECT_EQ(merged.metadata.ints.at("spp"), 5) << label;
            EXPECT_EQ(merged.metadata.ints.at("partial"), 0) << label;
            const Film& m = *merged.film;
            ASSERT_EQ(m.width(), kSize);
            ASSERT_EQ(m.height(), kSize);
            double sum = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    const std::string at =
                        label + " pixel " + std::to_string(x) + "," + std::to_string(y);
                    for (int c = 0; c < 3; ++c)
                        expectClose(m.pixel(x, y)[c], full.film->pixel(x, y)[c], at);
                    expectClose(m.varianceOfMean(x, y), full.film->varianceOfMean(x, y),
                                at + " variance");
                    for (int c = 0; c < 3; ++c)
                        expectClose(m.varianceOfMeanRgb(x, y)[c],
                                    full.film->varianceOfMeanRgb(x, y)[c], at + " variance RGB");
                    EXPECT_EQ(m.samples(x, y), full.film->samples(x, y)) << at;
                    EXPECT_EQ(m.sums(x, y).splatCount, full.film->sums(x, y).splatCount) << at;
                    sum += full.film->pixel(x, y)[1];
                    ASSERT_EQ(m.hasStokes(), mode == RenderModeKind::Polarised) << label;
                    if (m.hasStokes())
                        for (std::size_t i = 1; i < 4; ++i)
                            for (int c = 0; c < 3; ++c)
                                expectClose(m.stokes(x, y)[i][c], full.film->stokes(x, y)[i][c],
                                            at + " S" + std::to_string(i));
                    ASSERT_EQ(m.spectralFilm() != nullptr, mode != RenderModeKind::Rgb) << label;
                    if (!m.spectralFilm()) continue;
                    const std::size_t n = m.spectralFilm()->valuesPerPixel();
                    ASSERT_EQ(n, std::size_t(mode == RenderModeKind::Polarised ? 24 : 6));
                    std::vector<double> got(n), want(n);
                    m.spectralMean(x, y, got.data());
                    full.film->spectralMean(x, y, want.data());
                    for (std::size_t i = 0; i < n; ++i)
                        expectClose(got[i], want[i], at + " spectral value " + std::to_string(i));
                }
            EXPECT_GT(sum, 0) << label << ": the comparison needs a lit image";
        }
}

// Variance.R/G/B: the unbiased sample variance of each channel over n, from the sums the film
// keeps, exactly as computed by hand for four samples.
TEST(FilmVariance, PerChannelVarianceOfTheMeanIsTheSampleVarianceOverN) {
    Film film(2, 1, FilmSpace::Rec709);
    const double r[4] = {1, 2, 4, 7}, g[4] = {0.5, 0.5, 0.5, 0.5}, b[4] = {3, 0, 0, 1};
    for (int i = 0; i < 4; ++i)
        film.addSample(1, 0, Rgb<double>(r[i], g[i], b[i]), 1.0);
    const auto variance = [](const double* v) {
        double mean = 0, sq = 0;
        for (int i = 0; i < 4; ++i)
            mean += v[i] / 4;
        for (int i = 0; i < 4; ++i)
            sq += (v[i] - mean) * (v[i] - mean);
        return sq / 3 / 4;
    };
    const Rgb<double> got = film.varianceOfMeanRgb(1, 0);
    EXPECT_NEAR(got[0], variance(r), 1e-12);
    EXPECT_NEAR(got[1], 0.0, 1e-12);
    EXPECT_NEAR(got[2], variance(b), 1e-12);
    EXPECT_EQ(film.varianceOfMeanRgb(0, 0)[0], 0.0);
}

TEST_F(Shards, PathCropsTileTheFilmBitForBit) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Spectral);
    o.spp = 3;
    const RenderResult full = renderScene(scene, o);
    const std::vector<PixelBounds> tiles = {
        {0, 13, 0, 4}, {13, kSize, 0, 4}, {0, 1, 4, kSize}, {1, kSize, 4, kSize}};
    std::vector<int> covered(kSize * kSize, 0);
    for (const PixelBounds& t : tiles) {
        o.crop = t;
        const RenderResult r = renderScene(scene, o);
        ASSERT_EQ(r.film->width(), t.width());
        ASSERT_EQ(r.film->height(), t.height());
        for (int y = 0; y < t.height(); ++y)
            for (int x = 0; x < t.width(); ++x) {
                ++covered[std::size_t(t.y0 + y) * kSize + std::size_t(t.x0 + x)];
                for (int c = 0; c < 3; ++c)
                    ASSERT_EQ(r.film->pixel(x, y)[c], full.film->pixel(t.x0 + x, t.y0 + y)[c]);
            }
    }
    for (const int c : covered)
        ASSERT_EQ(c, 1);
}

TEST_F(Shards, OverlappingSamplesAreRefusedNamingBothFiles) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    const RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Rgb);
    const auto a = shard(scene, o, "first.exr", SampleRange{0, 4});
    const auto b = shard(scene, o, "second.exr", SampleRange{3, 2}, PixelBounds{5, 9, 5, 9});
    const std::string e = errorOf([&] { mergeShards({a, b}); });
    EXPECT_NE(e.find("first.exr and "), std::string::npos) << e;
    EXPECT_NE(e.find("second.exr: both hold samples 3:1"), std::string::npos) << e;
    // The same samples of disjoint crops belong together.
    const auto c = shard(scene, o, "third.exr", SampleRange{3, 2}, PixelBounds{0, 5, 0, 5});
    EXPECT_EQ(errorOf([&] { mergeShards({b, c}); }), "(accepted)");
}

TEST_F(Shards, MismatchedSettingsOrScenesAreRefused) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Rgb);
    const auto a = shard(scene, o, "seed1.exr", SampleRange{0, 1});
    o.seed = 99;
    const auto b = shard(scene, o, "seed99.exr", SampleRange{1, 1});
    std::string e = errorOf([&] { mergeShards({a, b}); });
    EXPECT_NE(e.find("seed1.exr and "), std::string::npos) << e;
    EXPECT_NE(e.find("seed99.exr: different settings (seed="), std::string::npos) << e;

    SceneDesc other = testing::sceneFromText(R"({
      "film": {"resolution": [20, 20]},
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "sphere", "radius": 1, "material": "m", "emission": {"radiance": 1}}]
    })");
    // A scene from text hashes its (absent) file: give it one that differs from the box.
    const auto file = write("other.json", "{}");
    other.file = file;
    other.inputFiles = {file};
    const auto c = shard(other, optionsFor(IntegratorKind::Path, RenderModeKind::Rgb), "other.exr",
                         SampleRange{1, 1});
    e = errorOf([&] { mergeShards({a, c}); });
    EXPECT_NE(e.find("other.exr: different scenes (scene hash"), std::string::npos) << e;
}

TEST_F(Shards, MissingSamplesAndPixelsAreReported) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    const RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Rgb);
    const MergedShards merged =
        mergeShards({shard(scene, o, "a.exr", SampleRange{0, 2}),
                     shard(scene, o, "b.exr", SampleRange{4, 2}, PixelBounds{0, 10, 0, kSize})});
    EXPECT_EQ(merged.metadata.strings.at("samples"), "0:2,4:2");
    EXPECT_EQ(merged.metadata.strings.at("samples_missing"), "2:2");
    EXPECT_EQ(merged.metadata.ints.at("incomplete_pixels"), 10 * kSize);
    ASSERT_EQ(merged.warnings.size(), 2u);
    EXPECT_EQ(merged.warnings[0], "no shard holds samples 2:2");
    EXPECT_EQ(merged.film->samples(3, 3), 4u);
    EXPECT_EQ(merged.film->samples(15, 3), 2u);
}

TEST_F(Shards, AnInterruptedShardMergesWithItsTrueCountAndIsFlagged) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o = optionsFor(IntegratorKind::Light, RenderModeKind::Rgb);
    o.samples = SampleRange{0, 8};
    auto& flag = renderInterruptFlag();
    // Interrupted after its first pass (one sample per pixel), like Ctrl-C would.
    const RenderResult r = renderScene(scene, o, [&](const RenderProgress&) { flag = true; });
    flag = false;
    ASSERT_TRUE(r.partial);
    ASSERT_EQ(r.spp, 1);
    ImageMetadata meta = renderMetadata(scene, o, r, {"test", "test"});
    addShardMetadata(meta, scene, o, r);
    const auto partial = dir_ / "partial.exr";
    writeShardExr(partial, *r.film, meta);

    const auto rest = shard(scene, o, "rest.exr", SampleRange{1, 7});
    const MergedShards merged = mergeShards({partial, rest});
    EXPECT_EQ(merged.metadata.ints.at("partial"), 1);
    EXPECT_EQ(merged.metadata.strings.at("partial_shards"), "partial.exr");
    EXPECT_EQ(merged.metadata.strings.at("samples"), "0:8");
    EXPECT_EQ(merged.metadata.ints.at("spp"), 8);
    ASSERT_EQ(merged.warnings.size(), 1u);
    EXPECT_NE(merged.warnings[0].find("interrupted"), std::string::npos);
    // Its true count: one splat iteration from the partial shard, seven from the other, and
    // the image of a single 8-sample render.
    EXPECT_EQ(merged.film->sums(4, 4).splatCount, 8u);
    RenderOptions full = optionsFor(IntegratorKind::Light, RenderModeKind::Rgb);
    full.spp = 8;
    const RenderResult single = renderScene(scene, full);
    for (int c = 0; c < 3; ++c)
        expectClose(merged.film->pixel(4, 4)[c], single.film->pixel(4, 4)[c], "pixel 4,4");
}

TEST_F(Shards, AnImageThatIsNotAShardIsRefused) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Rgb);
    o.spp = 1;
    const RenderResult r = renderScene(scene, o);
    const auto plain = dir_ / "plain.exr";
    writeExr(plain, *r.film, false, renderMetadata(scene, o, r, {"test", "test"}));
    const std::string e = errorOf([&] { mergeShards({plain}); });
    EXPECT_NE(e.find("plain.exr: lamina:shard: not a shard"), std::string::npos) << e;
}

TEST_F(Shards, ACropOutsideTheFilmIsRefused) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o = optionsFor(IntegratorKind::Path, RenderModeKind::Rgb);
    o.crop = PixelBounds{0, kSize + 1, 0, 4};
    const std::string e = errorOf([&] { renderScene(scene, o); });
    EXPECT_NE(e.find("--crop 0,21,0,4: expected 0 <= X0 < X1 <= 20"), std::string::npos) << e;
}

}  // namespace
}  // namespace lamina::render
