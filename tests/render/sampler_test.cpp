// The Sobol sampler's fast path (bit-reversed domain, table-driven Sobol dimension 1, the
// per-pixel part of the seed hash done once) must give exactly the numbers of its plain
// definition: Burley 2020's padded, Owen-scrambled 2D Sobol points, written out below the
// slow way. Equal bits, so images do not change when the implementation gets faster.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "lamina/core/chi_square_test.h"
#include "lamina/core/pcg32.h"
#include "lamina/render/sampler.h"

namespace lamina::render {
namespace {

using namespace sobol_detail;

std::uint32_t reverseBitsPlain(std::uint32_t x) {
    std::uint32_t r = 0;
    for (int b = 0; b < 32; ++b)
        if (x & (1u << b)) r |= 1u << (31 - b);
    return r;
}

std::uint32_t scramblePlain(std::uint32_t x, std::uint32_t seed) {
    return reverseBitsPlain(laineKarrasPermutation(reverseBitsPlain(x), seed));
}

float toFloatPlain(std::uint32_t v) {
    return std::min(kOneMinusEpsilon<float>, float(v >> 8) * 0x1p-24f);
}

// Dimension pair `dim` of sample `index`: the index shuffled by its own scramble, then Sobol
// dimensions 0 (van der Corput) and 1 of it, each scrambled with a seed of its own. The three
// seeds come from one 64-bit hash of (pixel, dim): its low half, its high half, and the high
// half of its product with Steele and Vigna's multiplier 0xd1342543de82ef95.
Vec2<float> sobolPointPlain(std::uint64_t pixelSeed, std::uint32_t index, std::uint32_t dim) {
    const std::uint64_t h = hashValues({pixelSeed, dim});
    const auto s = std::uint32_t(h);
    const auto seed1 = std::uint32_t(h >> 32);
    const auto seed2 = std::uint32_t((h * 0xd1342543de82ef95ULL) >> 32);
    const std::uint32_t shuffled = scramblePlain(index, s);
    return {toFloatPlain(scramblePlain(reverseBitsPlain(shuffled), seed1)),
            toFloatPlain(scramblePlain(sobolDimension1(shuffled), seed2))};
}

TEST(SobolSampler, ReverseBitsMatchesTheBitByBitDefinition) {
    Pcg32 rng(7);
    for (int i = 0; i < 10000; ++i) {
        const std::uint32_t x = rng.nextUint32();
        ASSERT_EQ(reverseBits(x), reverseBitsPlain(x)) << x;
    }
}

TEST(SobolSampler, ReversedDimension1TableMatchesTheLoop) {
    Pcg32 rng(11);
    for (int i = 0; i < 10000; ++i) {
        const std::uint32_t y = i < 64 ? std::uint32_t(i) : rng.nextUint32();
        ASSERT_EQ(kReversedSobolDimension1(y), reverseBits(sobolDimension1(reverseBits(y)))) << y;
    }
}

TEST(SobolSampler, FastPathGivesThePlainDefinitionsNumbers) {
    // Sample indices up to and beyond 2^20 (long renders, sample-range shards), 1D and 2D
    // requests interleaved as the integrators make them.
    for (const std::uint32_t index :
         {0u, 1u, 2u, 3u, 17u, 255u, 1u << 20, (1u << 20) + 5u, 0x7fffffffu, 0xffffffffu}) {
        for (const int x : {0, 3, 255}) {
            PixelSampler sampler(SamplerKind::Sobol, 42, x, 7, index);
            const std::uint64_t pixelSeed = hashValues({42, std::uint64_t(x), 7});
            for (std::uint32_t dim = 0; dim < 40; ++dim) {
                const Vec2<float> expected = sobolPointPlain(pixelSeed, index, dim);
                if (dim % 3 == 1) {
                    ASSERT_EQ(sampler.get1D(), expected.x) << index << " " << dim;
                } else {
                    const Vec2<float> got = sampler.get2D();
                    ASSERT_EQ(got.x, expected.x) << index << " " << dim;
                    ASSERT_EQ(got.y, expected.y) << index << " " << dim;
                }
            }
        }
    }
}

// Shards of a long render (`render --samples FIRST:COUNT`, `farm plan --time`) start far into
// the sequence. Every aligned block of 2^m consecutive sample indices, however far, is a
// (0, m, 2)-net in each dimension pair (the index shuffle maps aligned blocks onto aligned
// blocks, Sobol's (0, 2)-sequence makes each a net, Owen scrambling keeps it one): each of
// the 2^m cells of any shape 2^-a x 2^-(m-a) holds exactly one point, so no point repeats
// within a block; and no block repeats the first (an index wrapping at 2^20 would).
TEST(SobolSampler, AlignedBlocksBeyondTwoToTheTwentyAreNets) {
    constexpr int m = 20;
    constexpr std::uint32_t n = 1u << m;
    const auto point = [](std::uint32_t index) {
        PixelSampler sampler(SamplerKind::Sobol, 3, 5, 9, index);
        sampler.get2D();  // the pair after the first, as an integrator asks for them
        return sampler.get2D();
    };
    std::vector<Vec2<float>> first(n);
    for (std::uint32_t i = 0; i < n; ++i)
        first[i] = point(i);
    for (const std::uint32_t block : {1u, 5u, 2047u}) {  // indices from 2^20 to 2^31 - 2^20
        std::vector<std::uint8_t> square(n), wide(n), strata(n);
        std::uint32_t repeats = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const Vec2<float> u = point(block * n + i);
            if (u == first[i]) ++repeats;
            const auto cell = [&](int bitsX) {
                const std::uint32_t cx = std::uint32_t(u.x * float(1u << bitsX));
                const std::uint32_t cy = std::uint32_t(u.y * float(1u << (m - bitsX)));
                return (cx << (m - bitsX)) | cy;
            };
            ++square[cell(m / 2)];
            ++wide[cell(4)];
            ++strata[cell(m)];
        }
        EXPECT_EQ(repeats, 0u) << "block " << block;
        for (std::uint32_t c = 0; c < n; ++c) {
            ASSERT_EQ(square[c], 1) << "block " << block << " cell " << c;
            ASSERT_EQ(wide[c], 1) << "block " << block << " cell " << c;
            ASSERT_EQ(strata[c], 1) << "block " << block << " cell " << c;
        }
    }
}

// skip() moves past a dimension without computing it: every later number is the one the
// sampler gives when the skipped dimension is drawn (1D or 2D), for every kind of sampler.
TEST(PixelSamplerSkip, LaterDimensionsAreTheSameAsWhenTheSkippedOneIsDrawn) {
    const GlobalSobolNet net(8, 8);
    for (const SamplerKind kind :
         {SamplerKind::Sobol, SamplerKind::Independent, SamplerKind::SobolGlobal}) {
        for (const std::uint32_t index : {0u, 1u, 6u, 1000u}) {
            for (int skipped = 0; skipped < 8; ++skipped) {
                PixelSampler drawn(kind, 9, 4, 2, index, &net),
                    skipping(kind, 9, 4, 2, index, &net);
                for (int dim = 0; dim < 12; ++dim) {
                    if (dim == skipped) {
                        if (dim % 2)
                            drawn.get1D();
                        else
                            drawn.get2D();
                        skipping.skip();
                    } else if (dim % 3 == 1) {
                        ASSERT_EQ(drawn.get1D(), skipping.get1D()) << skipped << " " << dim;
                    } else {
                        const Vec2<float> a = drawn.get2D(), b = skipping.get2D();
                        ASSERT_EQ(a.x, b.x) << skipped << " " << dim;
                        ASSERT_EQ(a.y, b.y) << skipped << " " << dim;
                    }
                }
            }
        }
    }
}

// The seeds of the pairs come from one hash per pair (three 32-bit seeds from 64 bits), so the
// pairs must still be independent of one another: over 2^16 pixels at one sample index the 4D
// points (a0, b0, a1, b1) of two pairs fill a 4^4 grid uniformly (Pearson's chi-square, fixed
// seed, significance 1e-3), for neighbouring pairs and for pairs far apart. With the
// dimension left out of the hash (every pair the same seeds, tried once) the statistic is
// about 983 000 (the threshold is about 330); with the second coordinate's seed equal to the
// first's it stays below 260: the coordinates have different inputs, so that is no defect
// this test could see.
TEST(SobolSampler, PairsAreIndependentAcrossPixels) {
    for (const std::uint32_t index : {0u, 3u, 77u}) {
        for (const int gap : {1, 9}) {
            ChiSquareResult result;
            result.observed.assign(256, 0.0);
            result.expected.assign(256, 0.0);
            result.alpha = 1e-3;
            const int side = 256;
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    PixelSampler sampler(SamplerKind::Sobol, 1234, x, y, index);
                    const Vec2<float> p = sampler.get2D();
                    for (int k = 1; k < gap; ++k)
                        sampler.get2D();
                    const Vec2<float> q = sampler.get2D();
                    const auto cell = [](float u) { return int(u * 4.0f); };
                    const int c = ((cell(p.x) * 4 + cell(p.y)) * 4 + cell(q.x)) * 4 + cell(q.y);
                    result.observed[std::size_t(c)] += 1.0;
                }
            for (double& e : result.expected)
                e = double(side * side) / 256.0;
            ASSERT_TRUE(pearsonStatistic(std::size_t(side * side), result)) << result.message;
            EXPECT_TRUE(result.passed) << "index " << index << " gap " << gap << ": "
                                       << result.message << " statistic " << result.statistic;
        }
    }
}

TEST(IndependentSampler, OneDimensionTakesTheFirstOfTwoNumbers) {
    PixelSampler a(SamplerKind::Independent, 5, 1, 2, 3), b(SamplerKind::Independent, 5, 1, 2, 3);
    for (int i = 0; i < 100; ++i) {
        const float u = a.get1D();
        ASSERT_EQ(u, b.get2D().x);
    }
}

// ---- sobol-global: film positions from one global Sobol sequence (global_sobol_net.h) ----

namespace global_net {

// The global point of index g (dimensions 0 and 1 of the unscrambled Sobol sequence) as 32-bit
// fixed-point coordinates, and the pixel of a 2^m grid it falls in.
struct GlobalPoint {
    std::uint32_t u, v;
};
GlobalPoint globalPoint(std::uint64_t g) {
    return {reverseBitsPlain(std::uint32_t(g)), sobolDimension1(g)};
}
int pixelOf(std::uint32_t c, int m) {
    return m == 0 ? 0 : int(c >> (32 - m));
}

}  // namespace global_net

// The enumeration (Grünschloß et al. 2012) must find exactly what a search of the global
// sequence finds: sample j of pixel (x, y) is the j-th global point falling in that pixel, and
// its position in the pixel is the point's coordinates with the pixel's bits taken off. Images
// of several shapes (a 1 x 1 film is m = 0; non-square and non-power-of-two sides round up).
TEST(GlobalSobolNet, SampleJOfAPixelIsTheJthGlobalPointInIt) {
    using namespace global_net;
    constexpr int kSamples = 8;
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{2, 2}, std::pair{5, 3}, std::pair{8, 8},
                               std::pair{16, 9}, std::pair{3, 20}}) {
        const GlobalSobolNet net(w, h);
        const int m = net.log2Resolution();
        ASSERT_GE(1 << m, std::max(w, h));
        ASSERT_LT(1 << m, 2 * std::max(w, h));
        const int side = 1 << m;
        std::vector<std::vector<std::uint64_t>> found(std::size_t(side * side));
        for (std::uint64_t g = 0; g < std::uint64_t(side * side * kSamples); ++g) {
            const GlobalPoint p = globalPoint(g);
            found[std::size_t(pixelOf(p.v, m) * side + pixelOf(p.u, m))].push_back(g);
        }
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const auto& indices = found[std::size_t(y * side + x)];
                ASSERT_EQ(indices.size(), std::size_t(kSamples)) << w << "x" << h;
                for (int j = 0; j < kSamples; ++j) {
                    ASSERT_EQ(net.globalIndex(x, y, std::uint32_t(j)), indices[std::size_t(j)])
                        << w << "x" << h << " pixel " << x << "," << y << " sample " << j;
                    const GlobalPoint p = globalPoint(indices[std::size_t(j)]);
                    const Vec2<float> got =
                        net.pixelPosition(net.globalIndex(x, y, std::uint32_t(j)));
                    ASSERT_EQ(got.x, unitFloat(p.u << m));
                    ASSERT_EQ(got.y, unitFloat(p.v << m));
                }
            }
    }
}

// The (0, 2)-sequence property inside one pixel: any aligned block of 2^k samples of a pixel
// (the first, and one beyond 2^20 as a sample range starts) is a (0, k, 2)-net of the pixel,
// each cell 2^-a x 2^-(k-a) holding one point, on the largest film (m = 16) and a 4K one.
TEST(GlobalSobolNet, EachPixelsBlocksOfTwoToTheKSamplesAreNets) {
    constexpr int k = 8;
    constexpr int n = 1 << k;
    for (const auto& [w, h] : {std::pair{3840, 2160}, std::pair{65536, 7}}) {
        const GlobalSobolNet net(w, h);
        for (const auto& [x, y] : {std::pair{0, 0}, std::pair{w - 1, h - 1}, std::pair{1234, 5}})
            for (const std::uint32_t first : {0u, 1u << 20}) {
                for (int a = 0; a <= k; ++a) {
                    std::vector<int> cells(n, 0);
                    for (int j = 0; j < n; ++j) {
                        const Vec2<float> p =
                            net.pixelPosition(net.globalIndex(x, y, first + std::uint32_t(j)));
                        const int cx = int(p.x * float(1 << a)),
                                  cy = int(p.y * float(1 << (k - a)));
                        ++cells[std::size_t((cx << (k - a)) | cy)];
                    }
                    for (int c = 0; c < n; ++c)
                        ASSERT_EQ(cells[std::size_t(c)], 1)
                            << w << "x" << h << " pixel " << x << "," << y << " first " << first
                            << " a " << a << " cell " << c;
                }
            }
    }
}

// sobol-global stratifies a pixel's film positions and wavelengths together, as pbrt-v4's
// SobolSampler does: Sobol dimensions 0, 1 and 2 are a (1, 3)-sequence (Joe and Kuo 2008),
// so each aligned block of 2^k samples of a pixel, as (film x, film y, wavelength number) in
// the order the spectral mode draws them, is a (1, k, 3)-net of the pixel: every box of
// volume 2^(1-k) (2^-a x 2^-b x 2^-c, a + b + c = k - 1) holds two points; the Owen
// scramble of the wavelength number keeps that. The Sobol sampler's numbers (get1D, then
// get2D: independent pairs) fail it (tried once).
TEST(GlobalSobolNet, FilmPositionAndWavelengthAreAOneKThreeNetInEachPixel) {
    constexpr int k = 7;
    constexpr int n = 1 << k;
    const GlobalSobolNet net(320, 180);
    for (const auto& [x, y] : {std::pair{0, 0}, std::pair{319, 179}, std::pair{100, 57}})
        for (const std::uint32_t first : {0u, 3u << 20}) {
            std::vector<std::array<float, 3>> points;
            for (int j = 0; j < n; ++j) {
                PixelSampler sampler(SamplerKind::SobolGlobal, 5, x, y, first + std::uint32_t(j),
                                     &net);
                const float w = sampler.getWavelength1D();
                const Vec2<float> p = sampler.getPixel2D();
                points.push_back({p.x, p.y, w});
            }
            for (int a = 0; a < k; ++a)
                for (int b = 0; a + b < k; ++b) {
                    const int c = k - 1 - a - b;
                    std::vector<int> cells(n / 2, 0);
                    for (const auto& q : points) {
                        const int ca = int(q[0] * float(1 << a)), cb = int(q[1] * float(1 << b)),
                                  cc = int(q[2] * float(1 << c));
                        ++cells[std::size_t((((ca << b) | cb) << c) | cc)];
                    }
                    for (const int count : cells)
                        ASSERT_EQ(count, 2) << "pixel " << x << "," << y << " first " << first
                                            << " box " << a << "," << b << "," << c;
                }
        }
}

// The Sobol sampler's scramble is a proper nested uniform (Owen) scramble where it matters
// most, a pixel's footprint integral of something small and sharp: the indicator of a disk
// (an edge of every orientation; radius 0.05-0.3, inside the pixel, so its integral is
// pi r^2) integrated by a pixel's first N points. Over 128 random disks and pixels the RMS
// error must fall as Owen's N^-3/4 (Owen 1997, "Scrambled net variance for integrals of
// smooth functions"; for an edge the variance of a scrambled (0, m, 2)-net is O(N^-3/2)),
// slope within 0.1 of -0.75 between N = 16 and 1024 (fixed seeds; with 128 trials each RMS
// error is good to about 8%, the slope to about 0.03), and stay within 1.3x, both ways, of a
// true nested uniform scramble (a hash of every bit's prefix) of the same Sobol points.
// Independent numbers in its place fail it (slope -1/2, tried once); a random digital shift
// (XOR of a seed) passes it too: this is the error rate of a scrambled net, not a proof that
// the scramble is nested uniform.
TEST(SobolSampler, DiskFootprintErrorFallsAsAnOwenScrambles) {
    const auto owenScramble = [](std::uint32_t v, std::uint64_t seed) {
        std::uint32_t out = 0;
        for (int b = 0; b < 32; ++b) {
            const std::uint32_t prefix = b == 0 ? 0u : v >> (32 - b);
            const std::uint32_t flip =
                std::uint32_t(hashValues({seed, std::uint64_t(b), prefix}) >> 63);
            out |= (((v >> (31 - b)) & 1u) ^ flip) << (31 - b);
        }
        return out;
    };
    constexpr int kTrials = 128;
    const int sizes[2] = {16, 1024};
    double lamina[2] = {0, 0}, owen[2] = {0, 0};
    Pcg32 rng(2024);
    for (int t = 0; t < kTrials; ++t) {
        const double r = 0.05 + 0.25 * rng.nextFloat();
        const double cx = r + (1 - 2 * r) * rng.nextFloat(), cy = r + (1 - 2 * r) * rng.nextFloat();
        const double exact = kPi<double> * r * r;
        const auto inside = [&](double x, double y) {
            return sqr(x - cx) + sqr(y - cy) < r * r ? 1.0 : 0.0;
        };
        const std::uint64_t owenSeed = hashValues({31, std::uint64_t(t)});
        for (int s = 0; s < 2; ++s) {
            double sumLamina = 0, sumOwen = 0;
            for (int i = 0; i < sizes[s]; ++i) {
                PixelSampler sampler(SamplerKind::Sobol, 77, t, 3, std::uint32_t(i));
                const Vec2<float> u = sampler.get2D();
                sumLamina += inside(u.x, u.y);
                sumOwen += inside(
                    unitFloat(owenScramble(reverseBitsPlain(std::uint32_t(i)), owenSeed)),
                    unitFloat(owenScramble(sobolDimension1(std::uint32_t(i)), owenSeed + 1)));
            }
            lamina[s] += sqr(sumLamina / sizes[s] - exact);
            owen[s] += sqr(sumOwen / sizes[s] - exact);
        }
    }
    for (int s = 0; s < 2; ++s) {
        lamina[s] = std::sqrt(lamina[s] / kTrials);
        owen[s] = std::sqrt(owen[s] / kTrials);
        EXPECT_LT(lamina[s], 1.3 * owen[s]) << "N " << sizes[s];
        EXPECT_GT(lamina[s], owen[s] / 1.3) << "N " << sizes[s];
    }
    const double slope = std::log(lamina[1] / lamina[0]) / std::log(double(sizes[1]) / sizes[0]);
    EXPECT_NEAR(slope, -0.75, 0.1)
        << "RMS error " << lamina[0] << " at 16, " << lamina[1] << " at 1024";
}

}  // namespace
}  // namespace lamina::render
