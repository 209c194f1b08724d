// pbrt-v4's noise textures and texture mappings (procedural_textures.h, texture_mapping.h):
// values against pbrt-v4's definitions at fixed points, the mappings at points whose (s, t) is
// known by hand, a mirrored image, and the scene file's keys and errors.
//
// The reference values below were computed in double precision by a separate implementation
// of pbrt-v4's definitions (src/pbrt/util/noise.cpp and textures.h/.cpp), written for this test
// from the formulas and not from lamina's code:
//   noise(x, y, z): Perlin 2002's permutation P; the corner (i, j, k) of the cell of p has
//     h = P[P[P[i] + j] + k] & 15, ramp u(h) +- v(h) with u = dx if h < 8 or h in {12, 13}
//     else dy, v = dy if h < 4 or h in {12, 13} else dz (signs from bits 0 and 1), blended
//     trilinearly with the weights 6t^5 - 15t^4 + 10t^3;
//   fbm(p, omega, n) = sum_{i < n} omega^i noise(1.99^i p) (a zero footprint: all n octaves,
//     the partial one weighted 0), turbulence = sum omega^i |noise(1.99^i p)| + omega^n 0.2;
//   windy(p) = |fbm(p / 10, 0.5, 3)| fbm(p, 0.5, 6);
//   marble(p) = 1.5 Bezier_first(u) of pbrt-v4's nine colours, t = 1/2 + sin(q.y + variation
//     fbm(q, omega, n)) / 2, q = scale p, first = min(floor(6 t), 5), u = 6 t - first.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "lamina/core/math.h"
#include "lamina/output/image_output.h"
#include "lamina/scene/procedural_textures.h"
#include "lamina/scene/shading_normal_maps.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using ::testing::HasSubstr;

struct NoiseReference {
    Vec3<float> p;
    double fbm, wrinkled, windy, fbm3;  // fbm3: omega 0.7, 3 octaves
    std::array<double, 3> marble;       // octaves 8, omega 0.5, scale 1, variation 0.2
    std::array<double, 3> marble2;      // octaves 4, omega 0.6, scale 2.5, variation 0.5
};

const NoiseReference kReference[] = {
    {{0.3f, 0.7f, 0.2f},
     0.16181949302145782,
     0.30257195337077536,
     0.0165970790390379,
     0.2986942215416725,
     {0.869941068632306, 0.869941068632306, 0.899958127712428},
     {0.8692031743654697, 0.8692031743654697, 0.8994338344175705}},
    {{1.25f, -2.5f, 3.75f},
     0.15548211522237873,
     0.16293326139826017,
     0.09175714691022388,
     0.2178589348888928,
     {0.8647191583001206, 0.864685648462824, 0.8932481536073161},
     {0.873490024424713, 0.8690017949672728, 0.8841654979724105}},
    {{-4.1f, 0.35f, 7.9f},
     -0.6412499537513189,
     0.7705132789053489,
     -0.2969114995847082,
     -0.8575498090186527,
     {0.8721479619891133, 0.8687118134455398, 0.8872222840403116},
     {0.7369788929438891, 0.7369788929438891, 0.8054850028811844}},
};

// Float sums of up to 8 octaves at coordinates up to 1.99^7 |p| ~ 800 against double.
constexpr double kTolerance = 2e-4;

TEST(NoiseTextures, MatchPbrtV4sDefinitionsAtFixedPoints) {
    const TextureSpace identity;
    const FbmTexture fbm(identity, 8, 0.5f), fbm3(identity, 3, 0.7f);
    const WrinkledTexture wrinkled(identity, 8, 0.5f);
    const WindyTexture windy(identity);
    const MarbleTexture marble(identity, 8, 0.5f, 1.0f, 0.2f);
    const MarbleTexture marble2(identity, 4, 0.6f, 2.5f, 0.5f);
    for (const NoiseReference& r : kReference) {
        const TexturePoint at(Vec2<float>(0.5f), r.p);
        SCOPED_TRACE(::testing::Message() << r.p.x << " " << r.p.y << " " << r.p.z);
        EXPECT_NEAR(fbm.evaluate(at)[0], r.fbm, kTolerance);
        EXPECT_NEAR(fbm3.evaluate(at)[0], r.fbm3, kTolerance);
        EXPECT_NEAR(wrinkled.evaluate(at)[0], r.wrinkled, kTolerance);
        EXPECT_NEAR(windy.evaluate(at)[0], r.windy, kTolerance);
        // A grey value: all three channels alike.
        EXPECT_EQ(fbm.evaluate(at)[0], fbm.evaluate(at)[2]);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(marble.evaluate(at)[c], r.marble[std::size_t(c)], kTolerance);
            EXPECT_NEAR(marble2.evaluate(at)[c], r.marble2[std::size_t(c)], kTolerance);
        }
    }
}

// The point mapping reads the world point in the texture's space: a texture scaled by 3 at 3p
// is the unscaled one at p (pbrt-v4's textureFromRender = Inverse(renderFromTexture)).
TEST(NoiseTextures, ReadThePointInTheTexturesSpace) {
    const FbmTexture placed(
        TextureSpace::fromTransform(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
                                    glm::scale(glm::dmat4(1.0), glm::dvec3(3.0))),
        8, 0.5f);
    for (const NoiseReference& r : kReference) {
        const Vec3<float> world = 3.0f * r.p + Vec3<float>(1, 2, 3);
        EXPECT_NEAR(placed.evaluate(TexturePoint(Vec2<float>(0.0f), world))[0], r.fbm, kTolerance);
    }
}

// pbrt-v4's InsidePolkaDot at points of the reference implementation's grid: inside dots at
// the first five, outside at the next five.
TEST(DotsTexture, DotsWhereTheReferenceHasThem) {
    const std::pair<float, float> inside[] = {
        {-2.9f, -1.95f}, {-2.9f, 1.05f}, {-1.9f, -1.95f}, {-1.4f, 2.05f}, {-0.9f, -0.95f}};
    const std::pair<float, float> outside[] = {
        {-2.9f, -2.95f}, {-2.9f, -2.45f}, {-2.9f, -1.45f}, {-2.9f, -0.95f}, {-2.9f, -0.45f}};
    for (const auto& [s, t] : inside)
        EXPECT_TRUE(DotsTexture::insideDot(Vec2<float>(s, t))) << s << " " << t;
    for (const auto& [s, t] : outside)
        EXPECT_FALSE(DotsTexture::insideDot(Vec2<float>(s, t))) << s << " " << t;
    const DotsTexture dots(TextureMapping2D{}, std::make_shared<ConstantTexture>(Rgb<float>(1)),
                           std::make_shared<ConstantTexture>(Rgb<float>(0.25f)));
    EXPECT_EQ(dots.evaluate(Vec2<float>(-0.9f, -0.95f)), Rgb<float>(1));
    EXPECT_EQ(dots.evaluate(Vec2<float>(-2.9f, -2.95f)), Rgb<float>(0.25f));
}

// A bump map of a solid texture differences the height along the surface: on the plane z = 0
// with dp/du = 2 x, dp/dv = y and the normal z, the bumped normal is Blinn's (t_u + h_u n) x
// (t_v + h_v n) with h_u, h_v the central differences (step kBumpStep) of the height at
// p +- step dp/du and p +- step dp/dv. Were the point not moved with the uv step, a solid
// texture's differences would be 0 and the normal unchanged.
TEST(NoiseTextures, BumpMapsDifferenceThemAlongTheSurface) {
    const FbmTexture height(TextureSpace{}, 8, 0.5f);
    SurfaceDerivatives d;
    d.dpdu = Vec3<float>(2, 0, 0);
    d.dpdv = Vec3<float>(0, 1, 0);
    const Vec3<float> ns(0, 0, 1), p(0.3f, 0.7f, 0.2f);
    const auto h = [&](const Vec3<float>& q) {
        return double(height.evaluate(TexturePoint(Vec2<float>(0.0f), q))[0]);
    };
    const float e = kBumpStep;
    const double hu = (h(p + e * d.dpdu) - h(p - e * d.dpdu)) / (2 * e);
    const double hv = (h(p + e * d.dpdv) - h(p - e * d.dpdv)) / (2 * e);
    // (t_u + h_u n) x (t_v + h_v n) with t_u = 2 x, t_v = y (h dn = 0 on a plane).
    const Vec3<double> expected =
        glm::normalize(glm::cross(Vec3<double>(2, 0, hu), Vec3<double>(0, 1, hv)));
    const Vec3<float> n = bumpMappedNormal(height, TexturePoint(Vec2<float>(0.5f), p), ns, d);
    EXPECT_GT(std::abs(hu) + std::abs(hv), 0.1);  // the noise does slope here
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(n[c], expected[c], 1e-4) << c;
}

// pbrt-v4's 3D checkerboard: tex1 where floor(x) + floor(y) + floor(z) is even.
TEST(SolidCheckerboard, CellsOfTheTexturesSpace) {
    const SolidCheckerboardTexture c(Rgb<float>(1.0f), Rgb<float>(0.0f), TextureSpace{});
    const auto at = [&](float x, float y, float z) {
        return c.evaluate(TexturePoint(Vec2<float>(0.5f), Vec3<float>(x, y, z)))[0];
    };
    EXPECT_EQ(at(0.5f, 0.5f, 0.5f), 1.0f);
    EXPECT_EQ(at(1.5f, 0.5f, 0.5f), 0.0f);
    EXPECT_EQ(at(1.5f, 1.5f, 0.5f), 1.0f);
    EXPECT_EQ(at(1.5f, 1.5f, 1.5f), 0.0f);
    EXPECT_EQ(at(-0.5f, 0.5f, 0.5f), 0.0f);   // floor -1: odd
    EXPECT_EQ(at(-0.5f, -0.5f, 2.5f), 1.0f);  // -1 - 1 + 2
    EXPECT_EQ(at(3e7f, 0.5f, 0.5f), 1.0f);    // far out every float is even
    EXPECT_EQ(at(7.0f, 0.5f, 1e30f), 0.0f);
}

TextureMapping2D projected(TextureMappingKind kind, const glm::dmat4& worldFromTexture) {
    TextureMapping2D m;
    m.kind = kind;
    m.space = TextureSpace::fromTransform(worldFromTexture);
    return m;
}

void expectNear(const Vec2<float>& got, float s, float t) {
    EXPECT_NEAR(got.x, s, 1e-6f);
    EXPECT_NEAR(got.y, t, 1e-6f);
}

// (s, t) of each mapping at points where it is known by hand. The texture spaces are moved
// to (1, 2, 3) so that the transform is applied, not skipped.
TEST(TextureMappings, GiveTheKnownCoordinates) {
    const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3));
    const Vec3<float> origin(1, 2, 3);
    const auto at = [&](float x, float y, float z) {
        return TexturePoint(Vec2<float>(0.25f, 0.75f), origin + Vec3<float>(x, y, z));
    };
    // uv: scale uv + offset; a negative scale mirrors.
    TextureMapping2D uv;
    uv.scale = Vec2<float>(2.0f, -1.0f);
    uv.offset = Vec2<float>(0.5f, 0.0f);
    expectNear(uv.map(at(0, 0, 0)), 1.0f, -0.75f);
    // planar: (du + q . v1, dv + q . v2).
    TextureMapping2D planar = projected(TextureMappingKind::Planar, moved);
    planar.v1 = Vec3<float>(0.5f, 0, 0);
    planar.v2 = Vec3<float>(0, 0, -0.25f);
    planar.offset = Vec2<float>(0.5f, -0.5f);
    expectNear(planar.map(at(1, 7, 2)), 1.0f, -1.0f);
    // spherical: +z is theta 0, the equator at +x phi 0, at +y phi pi/2, at -y phi 3pi/2.
    const TextureMapping2D sphere = projected(TextureMappingKind::Spherical, moved);
    expectNear(sphere.map(at(0, 0, 2)), 0.0f, 0.0f);
    expectNear(sphere.map(at(3, 0, 0)), 0.5f, 0.0f);
    expectNear(sphere.map(at(0, 0.5f, 0)), 0.5f, 0.25f);
    expectNear(sphere.map(at(0, -1, 0)), 0.5f, 0.75f);
    expectNear(sphere.map(at(1, 1, -std::sqrt(2.0f))), 0.75f, 0.125f);
    expectNear(sphere.map(at(0, 0, 0)), 0.0f, 0.0f);  // no direction: (0, 0), not NaN
    // cylindrical: ((pi + atan2(y, x)) / 2 pi, z): -x is s = 0 (or 1), +x is 1/2.
    const TextureMapping2D cylinder = projected(TextureMappingKind::Cylindrical, moved);
    expectNear(cylinder.map(at(2, 0, 0.25f)), 0.5f, 0.25f);
    expectNear(cylinder.map(at(0, 1, -2)), 0.75f, -2.0f);
    expectNear(cylinder.map(at(0, -1, 5)), 0.25f, 5.0f);
    // A rotated space (Rotate 90 about x, as pbrt scenes write it): the cylinder's axis along
    // world -y, and world (0, 4, -1) is the texture's (0, -1, -4).
    const TextureMapping2D turned =
        projected(TextureMappingKind::Cylindrical,
                  glm::rotate(glm::dmat4(1.0), kPi<double> / 2, glm::dvec3(1, 0, 0)));
    expectNear(turned.map(TexturePoint(Vec2<float>(0.0f), Vec3<float>(0, 4, -1))), 0.25f, -4.0f);
}

// vscale -1 (what exporters write for images stored top row first) reads the image upside
// down: (u, v) looks up what (u, 1 - v) does unmirrored, exactly at texel centres.
TEST(TextureMappings, ANegativeScaleMirrorsAnImage) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("lamina-mirror-" + std::to_string(::getpid()) + ".png");
    const std::vector<float> px = {0.0f, 0.0f, 0.0f, 1.0f,  1.0f,  1.0f,
                                   0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f};
    writeRgb8(file, 2, 2, px);
    const ImageTexture plain(file, Vec2<float>(1.0f), false, false);
    const ImageTexture mirrored(file, Vec2<float>(1.0f, -1.0f), false, false);
    for (const float u : {0.25f, 0.75f})
        for (const float v : {0.25f, 0.75f})
            EXPECT_EQ(mirrored.evaluate(Vec2<float>(u, v)), plain.evaluate(Vec2<float>(u, 1 - v)));
    EXPECT_NE(mirrored.evaluate(Vec2<float>(0.25f, 0.25f)),
              plain.evaluate(Vec2<float>(0.25f, 0.25f)));
    std::filesystem::remove(file);
}

SceneDesc sceneWith(const std::string& texture) {
    return testing::sceneFromText(R"({"textures": {"t": )" + texture + R"(},
      "materials": {"m": {"type": "lambert", "reflectance": {"texture": "t"}}},
      "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
}

std::string sceneError(const std::string& texture) {
    return lamina::testing::errorOf([&] { sceneWith(texture); });
}

TEST(TextureMappings, SceneFilesNameThem) {
    const TexturePoint at(Vec2<float>(0.5f), Vec3<float>(0.3f, 0.7f, 0.2f));
    const SceneDesc fbm = sceneWith(R"({"type": "fbm", "octaves": 3, "roughness": 0.7})");
    EXPECT_NEAR(fbm.textures[0]->evaluate(at)[0], kReference[0].fbm3, kTolerance);
    const SceneDesc moved = sceneWith(R"({"type": "wrinkled",
        "mapping": {"type": "point", "transform": [{"scale": 2}]}})");
    EXPECT_NEAR(moved.textures[0]->evaluate(TexturePoint(Vec2<float>(0.0f), 2.0f * at.p))[0],
                kReference[0].wrinkled, kTolerance);
    const SceneDesc checks = sceneWith(R"({"type": "checkerboard", "a": 1, "b": 0,
        "mapping": {"type": "planar", "v1": [1, 0, 0], "v2": [0, 1, 0], "offset": [0.5, 0]}})");
    // s = 0.5 + x: x = 0.25 is in cell (0, 0), x = 0.75 in cell (1, 0).
    EXPECT_EQ(checks.textures[0]->evaluate(TexturePoint(Vec2<float>(0.0f), {0.25f, 0.25f, 9}))[0],
              1.0f);
    EXPECT_EQ(checks.textures[0]->evaluate(TexturePoint(Vec2<float>(0.0f), {0.75f, 0.25f, 9}))[0],
              0.0f);
    EXPECT_THAT(sceneError(R"({"type": "fbm", "octaves": 31})"), HasSubstr("octaves"));
    EXPECT_THAT(sceneError(R"({"type": "dots", "mapping": {"type": "point"}})"),
                HasSubstr("a 2D texture takes a uv, planar, spherical or cylindrical mapping"));
    // A checkerboard with a point mapping is pbrt-v4's 3D one: q = p / 2, (1.25, 0, 0) odd.
    const SceneDesc solid = sceneWith(R"({"type": "checkerboard", "a": 1, "b": 0,
        "mapping": {"type": "point", "transform": [{"scale": 2}]}})");
    EXPECT_EQ(solid.textures[0]->evaluate(TexturePoint(Vec2<float>(0.0f), {2.5f, 0, 0}))[0], 0.0f);
    EXPECT_EQ(solid.textures[0]->evaluate(TexturePoint(Vec2<float>(0.0f), {1.5f, 0, 0}))[0], 1.0f);
    EXPECT_THAT(sceneError(R"({"type": "marble", "mapping": {"type": "planar"}})"),
                HasSubstr("a solid texture takes the point mapping"));
    EXPECT_THAT(sceneError(R"({"type": "checkerboard", "scale": [1, 2],
        "mapping": {"type": "spherical"}})"),
                HasSubstr("belongs to the uv mapping"));
    EXPECT_THAT(sceneError(R"({"type": "checkerboard", "scale": [0, 2]})"),
                HasSubstr("a scale of 0"));
    EXPECT_THAT(sceneError(R"({"type": "dots", "mapping": {"type": "planar", "up": 1}})"),
                HasSubstr("up"));
}

// A diffuse plane under a uniform sky of radiance 2 reflects 2 x albedo wherever it is seen
// (it sees only the sky; the path integrator's lambert sample has weight albedo exactly, as in
// OrthographicCamera.ADiffusePlaneUnderAUniformSkyHasTheSameRadianceEverywhere). Its albedo is a
// checkerboard of 1 and 0 mapped by a planar mapping with v1 = 2 x, v2 = 2 y: cells 0.5 wide, 4
// pixels of the 16 x 16 image of the window [-1, 1]^2, so every pixel lies in one cell (a box
// filter of half a pixel) and half the cells are white: every pixel is 2 or 0 and the mean is
// 1, exactly. A uv-mapped checkerboard on the same rectangle would follow its own uv instead.
TEST(TextureMappings, APlanarCheckerboardSeenOrthographicallyIsHalfWhite) {
    const SceneDesc scene = testing::sceneFromText(R"({
      "camera": {"type": "orthographic", "position": [0, 0, -3], "look_at": [0, 0, 0],
                 "screen_window": [-1, 1, -1, 1]},
      "film": {"resolution": [16, 16], "filter": {"type": "box"}},
      "sampler": {"type": "independent", "spp": 8, "seed": 3},
      "textures": {"checks": {"type": "checkerboard", "a": 1, "b": 0,
                              "mapping": {"type": "planar", "v1": [2, 0, 0], "v2": [0, 2, 0],
                                          "transform": [{"translate": [0, 0, 7]}]}}},
      "materials": {"m": {"type": "lambert", "reflectance": {"texture": "checks"}}},
      "shapes": [{"type": "rectangle", "material": "m",
                  "transform": [{"scale": 10}, {"rotate": {"axis": [0, 1, 0], "angle": 180}}]}],
      "lights": [{"type": "environment", "radiance": 2}]
    })");
    RenderOptions o;
    const RenderResult r = renderScene(scene, o);
    int white = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const float v = r.film->pixel(x, y)[1];
            ASSERT_TRUE(std::abs(v - 2.0f) < 1e-5f || std::abs(v) < 1e-6f) << x << ", " << y;
            white += v > 1.0f;
        }
    EXPECT_EQ(white, 128);
    EXPECT_NEAR(lamina::testing::imageMean(*r.film, 1).mean, 1.0, 1e-5);
}

// pbrt-v4's directionmix weighs by |n . dir| with the geometric normal: a white sphere (a = 1,
// b = 0 along the view) under a uniform sky of radiance 1, seen orthographically with one
// bounce, is |n . view| = sqrt(1 - r^2) at distance r from its centre on the image (a convex
// surface sees the whole sky, so the reflected radiance is the reflectance). Pixels within
// r < 0.8 are checked against their centre's value (the box filter's average differs by less
// than 0.003 there).
TEST(DirectionMixTexture, WeighsByTheNormalsAlignment) {
    const SceneDesc scene = testing::sceneFromText(R"({
      "camera": {"type": "orthographic", "position": [0, 0, -3], "look_at": [0, 0, 0],
                 "screen_window": [-1.1, 1.1, -1.1, 1.1]},
      "film": {"resolution": [22, 22], "filter": {"type": "box"}},
      "integrator": {"max_depth": 1},
      "sampler": {"spp": 64, "seed": 3},
      "textures": {"facing": {"type": "direction_mix", "a": 1, "b": 0, "direction": [0, 0, -2]}},
      "materials": {"m": {"type": "lambert", "reflectance": {"texture": "facing"}}},
      "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
      "lights": [{"type": "environment", "radiance": 1}]
    })");
    RenderOptions o;
    const RenderResult r = renderScene(scene, o);
    int checked = 0;
    for (int y = 0; y < 22; ++y)
        for (int x = 0; x < 22; ++x) {
            const double px = -1.1 + 0.1 * (x + 0.5), py = 1.1 - 0.1 * (y + 0.5);
            const double r2 = px * px + py * py;
            if (r2 > 0.64) continue;
            EXPECT_NEAR(r.film->pixel(x, y)[1], std::sqrt(1 - r2), 0.005) << x << ", " << y;
            ++checked;
        }
    EXPECT_GT(checked, 150);
    const auto texture = [](const std::string& keys) {
        return lamina::testing::errorOf([&] {
            testing::sceneFromText(R"({"textures": {"t": {"type": "direction_mix", )" + keys +
                                   R"(}}, "materials": {"m": {"type": "lambert",
                                                  "reflectance": {"texture": "t"}}},
                 "shapes": [{"type": "sphere", "material": "m"}],
                 "lights": [{"type": "environment", "radiance": 1}]})");
        });
    };
    EXPECT_EQ(texture(R"("direction": [0, 0, 0])"),
              "<test scene>: textures.t.direction: expected a non-zero vector");
    // At a point of unknown normal (an alpha test's) the weight is 0: b.
    const DirectionMixTexture mix(std::make_shared<ConstantTexture>(Rgb<float>(1.0f)),
                                  std::make_shared<ConstantTexture>(Rgb<float>(0.25f)),
                                  Vec3<float>(0, 1, 0));
    EXPECT_EQ(mix.evaluate(TexturePoint(Vec2<float>(0.5f)))[0], 0.25f);
    EXPECT_NEAR(mix.evaluate(TexturePoint(Vec2<float>(0.5f), Vec3<float>(0.0f),
                                          glm::normalize(Vec3<float>(0, -1, 1))))[0],
                0.25f + 0.75f * std::sqrt(0.5f), 1e-6f);
}

}  // namespace
}  // namespace lamina::render
