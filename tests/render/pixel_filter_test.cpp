// Pixel filters: the triangle filter's samples follow its normalised shape (chi-square at
// significance 0.01) with weight 1; its reading (default radius 2); the gaussian's `sigma`
// (its default radius / 3 gives the image of a scene without the key, bit for bit; refused
// on other filters and out of range).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/render/pixel_filter.h"
#include "render_helpers.h"

namespace lamina {
namespace {

render::FilmDesc filmOf(const std::string& film) {
    return testing::sceneFromText(R"({"film": )" + film +
                                  R"(, "lights": [{"type": "environment", "radiance": 1}]})")
        .film;
}

TEST(TriangleFilter, SamplesFollowItsNormalisedShape) {
    const render::FilmDesc film = filmOf(R"({"filter": {"type": "triangle"}})");
    ASSERT_EQ(film.filter, render::FilterKind::Triangle);
    ASSERT_EQ(film.filterRadius, 2.0);  // pbrt-v4's default
    const render::PixelFilter filter(film);
    ChiSquareConfig config;
    config.domain = ChiSquareDomain::Plane;
    config.planeMin = Vec2d(-2.0, -2.0);
    config.planeMax = Vec2d(2.0, 2.0);
    config.cosThetaBins = config.phiBins = 32;
    config.sampleCount = 1000000;
    config.significance = testing::kSignificance;
    bool unitWeights = true;
    const auto result = runChiSquareTest(
        config,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            const auto s = filter.sample(Vec2<float>(rng.nextFloat(), rng.nextFloat()));
            unitWeights &= s.weight == 1.0f;
            return Vec3d(s.offset.x, s.offset.y, 0.0);
        },
        // (r - |x|)(r - |y|) / r^4: the filter normalised to integral 1.
        [&](const Vec3d& p) {
            return double(filter.normalizedWeight(Vec2<float>(float(p.x), float(p.y))));
        });
    EXPECT_TRUE(testing::passes(result));
    EXPECT_NEAR(result.pdfIntegral, 1.0, 1e-3);
    EXPECT_TRUE(unitWeights);
    EXPECT_EQ(filter.evaluate1D(0.5f), 1.5f);
    EXPECT_EQ(filter.evaluate1D(2.5f), 0.0f);
}

TEST(GaussianFilter, SigmaDefaultsToAThirdOfTheRadiusBitForBit) {
    const auto render = [](const std::string& filter) {
        render::RenderOptions o;
        o.spp = 8;
        return render::renderScene(testing::sceneFromText(R"({
          "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
          "film": {"resolution": [12, 12], "filter": )" + filter +
                                                          R"(},
          "materials": {"m": {"type": "lambert", "reflectance": 0.6}},
          "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
          "lights": [{"type": "point", "position": [2, 3, -3], "intensity": 20},
                     {"type": "environment", "radiance": 0.3}]})"),
                                   o);
    };
    const auto implicit = render(R"({"type": "gaussian", "radius": 1.5})");
    const auto explicitSigma = render(R"({"type": "gaussian", "radius": 1.5, "sigma": 0.5})");
    const auto wider = render(R"({"type": "gaussian", "radius": 1.5, "sigma": 0.7})");
    bool differs = false;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(implicit.film->pixel(x, y)[c], explicitSigma.film->pixel(x, y)[c]);
                differs |= implicit.film->pixel(x, y)[c] != wider.film->pixel(x, y)[c];
            }
    EXPECT_TRUE(differs);  // the key is used
}

TEST(GaussianFilter, SigmaIsRefusedWhereItMeansNothing) {
    const auto errorOf = [](const std::string& film) {
        try {
            filmOf(film);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"({"filter": {"type": "triangle", "sigma": 0.5}})"),
                ::testing::HasSubstr("film.filter.sigma: only a gaussian filter takes sigma"));
    EXPECT_THAT(errorOf(R"({"filter": {"type": "gaussian", "radius": 2, "sigma": 0.1}})"),
                ::testing::HasSubstr("film.filter.sigma"));
    EXPECT_THAT(errorOf(R"({"filter": {"type": "gaussian", "radius": 1, "sigma": 5}})"),
                ::testing::HasSubstr("film.filter.sigma"));
    // Mitsuba 3's default gaussian: stddev 0.5 cut off at 4 stddev.
    EXPECT_EQ(filmOf(R"({"filter": {"type": "gaussian", "radius": 2, "sigma": 0.5}})").filterSigma,
              0.5);
}

}  // namespace
}  // namespace lamina
