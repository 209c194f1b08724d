// Environment mappings and orientation: the equal-area octahedral mapping (round trips, equal
// solid angles, pbrt-v4's orientation), importance sampling against its density by chi-square
// (equirectangular and octahedral, with and without a transform; family-wise significance
// 0.01 over the four), a render under an octahedral map against the same sky as an
// equirectangular map, and the `transform` key (a rotation equals the image rotated; what is
// refused). The white furnace in both mappings is in environment_map_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/lights/environment_map.h"
#include "lamina/lights/equal_area_sphere.h"
#include "lamina/output/image_output.h"
#include "render_helpers.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;
using render::EnvironmentLayout;
using render::EnvironmentMap;
using render::EnvironmentMapping;

// The angle between two unit vectors, accurate for small angles.
double angleBetween(const Vec3d& a, const Vec3d& b) {
    return 2 * std::asin(std::min(1.0, glm::length(a - b) / 2));
}

// n directions of a spherical Fibonacci lattice, and the six axes.
std::vector<Vec3d> latticeDirections(int n) {
    std::vector<Vec3d> ws{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const double golden = kPi<double> * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z);
        ws.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return ws;
}

TEST(EqualAreaSphere, RoundTripsWithinANanoradian) {
    double worstAngle = 0;
    for (const Vec3d& w : latticeDirections(200000))
        worstAngle = std::max(
            worstAngle,
            angleBetween(w, render::equalAreaSquareToSphere(render::equalAreaSphereToSquare(w))));
    EXPECT_LT(worstAngle, 1e-9);
    // Square -> sphere -> square inside the square (its border is where points pair up).
    double worstUv = 0;
    for (int i = 0; i < 401; ++i)
        for (int j = 0; j < 401; ++j) {
            const Vec2d uv((i + 0.5) / 401, (j + 0.5) / 401);
            const Vec2d back = render::equalAreaSphereToSquare(render::equalAreaSquareToSphere(uv));
            worstUv = std::max({worstUv, std::abs(back.x - uv.x), std::abs(back.y - uv.y)});
        }
    EXPECT_LT(worstUv, 1e-9);
}

TEST(EqualAreaSphere, FollowsPbrtV4sOrientation) {
    // The centre is +z, the corners -z, the edges' midpoints the equator's +-x and +-y, the
    // diamond between them the equator.
    const auto near = [](const Vec2d& uv, const Vec3d& expected) {
        const Vec3d w = render::equalAreaSquareToSphere(uv);
        EXPECT_LT(angleBetween(w, expected), 1e-12) << uv.x << ", " << uv.y;
        EXPECT_NEAR(glm::length(w), 1.0, 1e-12);
    };
    near({0.5, 0.5}, {0, 0, 1});
    near({1.0, 0.5}, {1, 0, 0});
    near({0.0, 0.5}, {-1, 0, 0});
    near({0.5, 1.0}, {0, 1, 0});
    near({0.5, 0.0}, {0, -1, 0});
    for (const Vec2d corner : {Vec2d(0, 0), Vec2d(1, 0), Vec2d(0, 1), Vec2d(1, 1)})
        near(corner, {0, 0, -1});
    near({0.75, 0.75}, glm::normalize(Vec3d(1, 1, 0)));
    near({0.25, 0.75}, glm::normalize(Vec3d(-1, 1, 0)));
}

TEST(EqualAreaSphere, EveryPixelCoversTheSameSolidAngle) {
    // Uniform directions (fixed seed) binned by their pixel of an N x N image: a pixel's share
    // estimates its solid angle over 4 pi, which the mapping makes 1 / N^2. The counts are
    // binomial, standard deviation sqrt(M p (1 - p)) with p = 1 / 64: 0.4% of the expected
    // 62500; every pixel must lie within 5 standard deviations (a false alarm 6e-7 per pixel).
    constexpr int kN = 8, kSamples = 4000000;
    std::vector<int> counts(kN * kN, 0);
    Pcg32 rng(2008);
    for (int i = 0; i < kSamples; ++i) {
        const double z = 1 - 2 * rng.nextDouble(), phi = 2 * kPi<double> * rng.nextDouble();
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        const Vec2d uv =
            render::equalAreaSphereToSquare(Vec3d(r * std::cos(phi), r * std::sin(phi), z));
        ++counts[std::size_t(std::min(int(uv.y * kN), kN - 1) * kN +
                             std::min(int(uv.x * kN), kN - 1))];
    }
    const double p = 1.0 / (kN * kN), expected = kSamples * p;
    const double sd = std::sqrt(kSamples * p * (1 - p));
    for (int i = 0; i < kN * kN; ++i)
        EXPECT_LT(std::abs(counts[std::size_t(i)] - expected), 5 * sd) << "pixel " << i;
}

// An oblique rotation followed by a mirror: what a transform may be.
Mat3<double> obliqueOrientation() {
    const Mat3<double> rotation(
        glm::rotate(Mat4<double>(1.0), glm::radians(50.0), glm::normalize(Vec3d(1, 2, 3))));
    return Mat3<double>(glm::scale(Mat4<double>(1.0), Vec3d(-1, 1, 1))) * rotation;
}

::testing::AssertionResult samplingMatchesItsDensity(const EnvironmentMap& map) {
    ChiSquareConfig config;
    config.sampleCount = 500000;
    config.significance = testing::kSignificance;
    config.testCount = 4;
    return testing::passes(runChiSquareTest(
        config,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            float pdf;
            const Vec3<float> w = map.sample(Vec2<float>(rng.nextFloat(), rng.nextFloat()), pdf);
            if (!(pdf > 0)) return std::nullopt;
            return Vec3d(w);
        },
        [&](const Vec3d& w) { return double(map.pdf(Vec3<float>(w))); }));
}

TEST(EnvironmentSampling, EquirectangularMatchesItsDensity) {
    EXPECT_TRUE(
        samplingMatchesItsDensity(EnvironmentMap(64, 32, testing::skyTestImage(64, 32), {})));
}

TEST(EnvironmentSampling, EquirectangularWithATransformMatchesItsDensity) {
    const EnvironmentLayout layout{EnvironmentMapping::Equirectangular, 30.0, obliqueOrientation()};
    EXPECT_TRUE(
        samplingMatchesItsDensity(EnvironmentMap(64, 32, testing::skyTestImage(64, 32), layout)));
}

TEST(EnvironmentSampling, EqualAreaOctahedralMatchesItsDensity) {
    const EnvironmentLayout layout{EnvironmentMapping::EqualAreaOctahedral, 0.0, Mat3<double>(1.0)};
    EXPECT_TRUE(
        samplingMatchesItsDensity(EnvironmentMap(32, 32, testing::skyTestImage(32, 32), layout)));
}

TEST(EnvironmentSampling, EqualAreaOctahedralWithATransformMatchesItsDensity) {
    const EnvironmentLayout layout{EnvironmentMapping::EqualAreaOctahedral, -45.0,
                                   obliqueOrientation()};
    EXPECT_TRUE(
        samplingMatchesItsDensity(EnvironmentMap(32, 32, testing::skyTestImage(32, 32), layout)));
}

// Files for the renders, removed with the fixture.
class EnvironmentFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("lamina-envmap-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Writes a float EXR whose pixel (x, y) (rows from the top) is f(x, y).
    std::string write(const std::string& name, int w, int h,
                      const std::function<Rgb<float>(int, int)>& f) const {
        const fs::path file = dir_ / name;
        std::vector<float> data;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    data.push_back(f(x, y)[c]);
        render::writeFloatExr(file, w, h, {"R", "G", "B"}, data);
        return file.string();
    }

    fs::path dir_;
};

// A smooth sky with no symmetry, so that a wrong orientation of either mapping would show.
Rgb<float> smoothSky(const Vec3d& w) {
    return Rgb<float>(float(1.0 + 0.6 * w.x), float(1.0 + 0.5 * w.y + 0.3 * w.z * w.z),
                      float(0.8 + 0.4 * w.z + 0.2 * w.x * w.y));
}

TEST_F(EnvironmentFiles, AnOctahedralMapRendersAsTheSameSkyInEquirectangular) {
    // The same sky sampled at the pixel centres of a 128^2 octahedral and a 256 x 128
    // latitude-longitude image (pixels of about 1.6 degrees in both), under one transform.
    constexpr int kN = 128;
    const std::string octahedral = write("octahedral.exr", kN, kN, [](int x, int y) {
        return smoothSky(render::equalAreaSquareToSphere({(x + 0.5) / kN, (y + 0.5) / kN}));
    });
    const std::string latLong = write("latlong.exr", 2 * kN, kN, [](int x, int y) {
        const double phi = ((x + 0.5) / (2 * kN) - 0.5) * 2 * kPi<double>,
                     theta = (y + 0.5) / kN * kPi<double>;
        return smoothSky(
            {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)});
    });
    const auto render = [](const std::string& file, const std::string& mapping) {
        render::RenderOptions o;
        o.spp = 64;
        return render::renderScene(testing::sceneFromText(R"({
          "camera": {"position": [0, 0.5, -4], "look_at": [0, 0, 0], "fov": 45},
          "film": {"resolution": [20, 20]},
          "integrator": {"max_depth": 4},
          "materials": {"m": {"type": "lambert", "reflectance": 0.7}},
          "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
          "lights": [{"type": "environment", "file": ")" + file +
                                                          R"(", "mapping": ")" + mapping +
                                                          R"(", "rotate": 20,
                      "transform": [{"rotate": {"axis": [1, 1, 0], "angle": 40}}]}]})"),
                                   o);
    };
    const auto a = render(octahedral, "equal_area_octahedral");
    const auto b = render(latLong, "equirectangular");
    // The two images estimate the same integrals but for the images' discretisation (the
    // sky's gradient is at most 0.7 per radian: about 1% across a pixel): each pixel agrees
    // within 5 combined standard errors plus 2%, each channel's image mean within 4 plus 0.5%.
    for (int c = 0; c < 3; ++c) {
        const auto ma = testing::imageMean(*a.film, c), mb = testing::imageMean(*b.film, c);
        EXPECT_LT(std::abs(ma.mean - mb.mean),
                  4 * std::hypot(ma.standardError, mb.standardError) + 0.005 * ma.mean)
            << "channel " << c;
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 20; ++x) {
                const double va = a.film->pixel(x, y)[c], vb = b.film->pixel(x, y)[c];
                const double se =
                    std::sqrt(a.film->varianceOfMean(x, y) + b.film->varianceOfMean(x, y));
                EXPECT_LT(std::abs(va - vb), 5 * se + 0.02 * va) << x << ", " << y << ", " << c;
            }
    }
}

TEST_F(EnvironmentFiles, ANonSquareOctahedralMapIsRefused) {
    const std::string file = write("wide.exr", 4, 2, [](int, int) { return Rgb<float>(1.0f); });
    try {
        EnvironmentMap(file, {EnvironmentMapping::EqualAreaOctahedral, 0.0, Mat3<double>(1.0)});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr(
                                  "wide.exr: an equal_area_octahedral environment map must be "
                                  "square, got 4 x 2 pixels"));
    }
}

// The orientation a scene's environment `transform` reads to.
Mat3<double> orientationOf(const std::string& file, const std::string& transform) {
    return std::get<render::EnvironmentLightDesc>(
               testing::sceneFromText(R"({"lights": [{"type": "environment", "file": ")" + file +
                                      R"(", "transform": )" + transform + "}]}")
                   .lights.at(0))
        .orientation;
}

TEST_F(EnvironmentFiles, ARotationAboutYEqualsTheImageRotated) {
    // Turning the map by 90 degrees about +y moves the sky by a quarter turn in azimuth: the
    // image with its columns shifted by a quarter of the width. At every pixel centre (far
    // from the pixels' edges, where rounding could change the nearest pixel) the lookups are
    // the same pixels, and the densities the same up to rounding.
    constexpr int kW = 64, kH = 32;
    const std::vector<Rgb<float>> image = testing::skyTestImage(kW, kH);
    std::vector<Rgb<float>> shifted(image.size());
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            shifted[std::size_t(y * kW + x)] = image[std::size_t(y * kW + (x - kW / 4 + kW) % kW)];
    const std::string file = write("sky.exr", 2, 1, [](int, int) { return Rgb<float>(1.0f); });
    const Mat3<double> turn =
        orientationOf(file, R"([{"rotate": {"axis": [0, 1, 0], "angle": 90}}])");
    const EnvironmentMap transformed(kW, kH, image,
                                     {EnvironmentMapping::Equirectangular, 0.0, turn});
    const EnvironmentMap rotated(kW, kH, image,
                                 {EnvironmentMapping::Equirectangular, 90.0, Mat3<double>(1.0)});
    const EnvironmentMap reference(kW, kH, shifted, {});
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const double phi = ((x + 0.5) / kW - 0.5) * 2 * kPi<double>,
                         theta = (y + 0.5) / kH * kPi<double>;
            const Vec3<float> w(Vec3d(std::sin(theta) * std::sin(phi), std::cos(theta),
                                      std::sin(theta) * std::cos(phi)));
            for (const EnvironmentMap* m : {&transformed, &rotated}) {
                ASSERT_EQ(m->lookup(w), reference.lookup(w)) << x << ", " << y;
                ASSERT_NEAR(m->pdf(w), reference.pdf(w), 1e-5 * reference.pdf(w) + 1e-12);
            }
        }
}

TEST_F(EnvironmentFiles, TheTransformTakesRotationsAndReflectionsOnly) {
    const std::string file = write("sky.exr", 2, 1, [](int, int) { return Rgb<float>(1.0f); });
    // A mirror is orthogonal: accepted, with determinant -1.
    EXPECT_NEAR(glm::determinant(orientationOf(file, R"([{"scale": [-1, 1, 1]}])")), -1.0, 1e-12);
    const auto errorOf = [&](const std::string& transform) {
        try {
            orientationOf(file, transform);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf(R"([{"scale": 2}])"),
                ::testing::HasSubstr("lights[0].transform: an environment takes rotations only "
                                     "(and mirror reflections such as a scale of [-1, 1, 1]); got "
                                     "a scale or shear"));
    EXPECT_THAT(
        errorOf(R"([{"rotate": {"axis": [0, 0, 1], "angle": 10}}, {"scale": [1, 1.5, 1]}])"),
        ::testing::HasSubstr("got a scale or shear"));
    EXPECT_THAT(errorOf(R"([{"matrix": [1, 0.5, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}])"),
                ::testing::HasSubstr("got a scale or shear"));
    EXPECT_THAT(errorOf(R"([{"translate": [0, 1, 0]}])"),
                ::testing::HasSubstr("lights[0].transform: an environment takes rotations only; "
                                     "got a translation"));
    try {
        testing::sceneFromText(R"({"lights": [{"type": "environment", "file": ")" + file +
                               R"(", "mapping": "cube"}]})");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("lights[0].mapping"));
    }
}

}  // namespace
}  // namespace lamina
