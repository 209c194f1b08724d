// Bump and normal maps (shading_normal_maps.h) through the geometry, on every kind of shape,
// against closed forms: a height h = a u on a flat rectangle turns the normal to
// normalize(-a, 0, |dp/du|) in the rectangle's frame, on a disk (h = a u, u the radius over R)
// to normalize(R n - a r), on a sphere (h = a v) to normalize((1 + h / r) pi r n - a theta), and
// under an instance's rotation and scale to the same with the world's dp/du; a constant height
// leaves every normal as it was (on the sphere only through the h dn/du term); a normal map of
// the flat colour (0.5, 0.5, 1) is the identity and one of (0.5 + sin t / 2, 0.5, 0.5 + cos t / 2)
// turns the normal by t towards dp/du. The reader's refusals. Ramps are EXR images of N texels
// along u (or v), exactly linear between the first and the last texel centres.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "lamina/geometry/geometry.h"
#include "lamina/image/image_io.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using testing::errorOf;
using ::testing::HasSubstr;

constexpr int kTexels = 64;

class ShadingNormalMaps : public testing::ScratchDirectoryTest {
  protected:
    void SetUp() override {
        ScratchDirectoryTest::SetUp();
        // Texel i's centre is at (i + 1/2) / N and holds that value: h(u) = u on
        // [1 / 2N, 1 - 1 / 2N]. The v ramp is one column, v = 0 at the bottom row.
        std::vector<float> u, v;
        for (int i = 0; i < kTexels; ++i) {
            const float c = (float(i) + 0.5f) / kTexels;
            u.insert(u.end(), {c, c, c});
            const float r = 1.0f - c;  // row i from the top
            v.insert(v.end(), {r, r, r});
        }
        writeFloatExr(dir_ / "ramp_u.exr", kTexels, 1, {"R", "G", "B"}, u);
        writeFloatExr(dir_ / "ramp_v.exr", 1, kTexels, {"R", "G", "B"}, v);
    }

    // A scene of `shapes` whose material "m" has `maps` (the material's extra keys), with the
    // ramps as textures "u ramp" and "v ramp" times `a`, and flat colours.
    SceneDesc scene(const std::string& maps, const std::string& shapes, double a = 0.0,
                    const std::string& objects = "{}") const {
        const std::string dir = dir_.string();
        return testing::sceneFromText(R"({
          "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0]},
          "lights": [{"type": "point", "position": [0, 0, 20], "intensity": 1}],
          "textures": {
            "u image": {"type": "image", "file": ")" +
                                      dir + R"(/ramp_u.exr"},
            "v image": {"type": "image", "file": ")" +
                                      dir + R"(/ramp_v.exr"},
            "u ramp": {"type": "scale", "texture": "u image", "scale": )" +
                                      std::to_string(a) + R"(},
            "v ramp": {"type": "scale", "texture": "v image", "scale": )" +
                                      std::to_string(a) + R"(},
            "height 0.3": {"type": "checkerboard", "a": 0.3, "b": 0.3},
            "flat": {"type": "checkerboard", "a": [0.5, 0.5, 1], "b": [0.5, 0.5, 1]},
            "tilted": {"type": "checkerboard", "a": [0.75, 0.5, 0.9330127], "b": [0.75, 0.5, 0.9330127]}
          },
          "materials": {"m": {"type": "lambert")" +
                                      (maps.empty() ? "" : ", " + maps) + R"(}},
          "objects": )" + objects + R"(,
          "shapes": [)" + shapes + R"(]
        })");
    }
};

SurfaceHit hitAt(const Geometry& g, const Vec3f& target, const Vec3f& from) {
    const auto hit = g.intersect(from, glm::normalize(target - from));
    EXPECT_TRUE(hit.has_value()) << "no hit towards " << target.x << " " << target.y << " "
                                 << target.z;
    return hit.value_or(SurfaceHit{});
}

void expectNear(const Vec3f& got, const Vec3<double>& want, const std::string& where) {
    constexpr double kTolerance = 2e-4;  // float hits, central differences of float lookups
    EXPECT_NEAR(got.x, want.x, kTolerance) << where;
    EXPECT_NEAR(got.y, want.y, kTolerance) << where;
    EXPECT_NEAR(got.z, want.z, kTolerance) << where;
}

// The rectangle [-2, 2] x [-1, 1] (scale [2, 1, 1]) in the plane z = 0: u = (x + 2) / 4, so
// dp/du = (4, 0, 0), dp/dv = (0, 2, 0), and h = a u turns the normal to normalize(-a, 0, 4).
constexpr const char* kWideRectangle =
    R"({"type": "rectangle", "material": "m", "transform": [{"scale": [2, 1, 1]}]})";

TEST_F(ShadingNormalMaps, ALinearHeightOnARectangleTiltsTheNormalByItsSlope) {
    for (const double a : {0.5, 2.0, 7.0}) {
        const SceneDesc s = scene(R"("displacement": {"texture": "u ramp"})", kWideRectangle, a);
        const Geometry g(s);
        for (const Vec3f p : {Vec3f(-1.5f, 0.3f, 0), Vec3f(0.1f, -0.7f, 0), Vec3f(1.6f, 0.9f, 0)}) {
            const SurfaceHit hit = hitAt(g, p, p + Vec3f(0.3f, 0.2f, 5));
            expectNear(hit.ns, glm::normalize(Vec3<double>(-a, 0, 4)),
                       "a = " + std::to_string(a) + " at x = " + std::to_string(p.x));
            expectNear(hit.ng, Vec3<double>(0, 0, 1), "the geometric normal stays");
        }
    }
}

// The same rectangle placed by an instance that rotates it and scales it by 1.5: dp/du is the
// rotated (6, 0, 0), so the normal is the rotated normalize(-a, 0, 6).
TEST_F(ShadingNormalMaps, InstancesTurnTheNormalWithTheWorldsDerivatives) {
    const double a = 2.0;
    const SceneDesc s =
        scene(R"("displacement": {"texture": "u ramp"})",
              R"({"type": "instance", "object": "quad", "transform": [{"scale": 1.5},
            {"rotate": {"axis": [1, 1, 0], "angle": 40}}, {"translate": [0.2, -0.1, 0.3]}]})",
              a, std::string(R"({"quad": [)") + kWideRectangle + "]}");
    const Geometry g(s);
    const glm::dmat3 rotation(
        glm::rotate(glm::dmat4(1.0), glm::radians(40.0), glm::normalize(glm::dvec3(1, 1, 0))));
    const glm::dvec3 translation(0.2, -0.1, 0.3);
    for (const glm::dvec3 local : {glm::dvec3(-1.2, 0.4, 0), glm::dvec3(0.9, -0.5, 0)}) {
        const Vec3f p(rotation * (1.5 * local) + translation);
        const SurfaceHit hit = hitAt(g, p, p + Vec3f(rotation * glm::dvec3(0.2, 0.1, 4)));
        expectNear(hit.ng, rotation * glm::dvec3(0, 0, 1), "the rotation as the test reads it");
        expectNear(hit.ns, rotation * glm::normalize(glm::dvec3(-a, 0, 6)),
                   "x = " + std::to_string(local.x));
    }
}

// A disk of radius R = 2 facing +z: u = rho / R, dp/du = R r, dp/dv = 2 pi rho phi; h = a u
// makes dp'/du x dp'/dv proportional to R n - a r.
TEST_F(ShadingNormalMaps, ARadialHeightOnADiskTiltsTheNormalOutwards) {
    const double a = 1.5, radius = 2.0;
    const SceneDesc s =
        scene(R"("displacement": {"texture": "u ramp"})",
              R"({"type": "disk", "material": "m", "center": [0, 0, 0], "normal": [0, 0, 1],
                  "radius": 2})",
              a);
    const Geometry g(s);
    for (const Vec3f p : {Vec3f(0.5f, 0.3f, 0), Vec3f(-1.2f, 0.8f, 0), Vec3f(0.1f, -1.7f, 0)}) {
        const SurfaceHit hit = hitAt(g, p, p + Vec3f(0, 0.1f, 5));
        const glm::dvec3 r = glm::normalize(glm::dvec3(p.x, p.y, 0));
        expectNear(hit.ns, glm::normalize(radius * glm::dvec3(0, 0, 1) - a * r),
                   "at " + std::to_string(p.x) + ", " + std::to_string(p.y));
    }
}

// A sphere of radius r = 1.5: u = phi / 2 pi + 1/2, v = theta / pi, dp/dv = pi r theta-hat,
// dn/dv = dp/dv / r. h = a v: dp'/du = (1 + h / r) dp/du, dp'/dv = (1 + h / r) dp/dv + a n, and
// the normal is normalize((1 + h / r) pi r n - a theta-hat): the h dn/dv term is in it.
TEST_F(ShadingNormalMaps, AHeightAlongThetaOnASphereGivesTheClosedForm) {
    const double a = 0.8, r = 1.5;
    const SceneDesc s = scene(R"("displacement": {"texture": "v ramp"})",
                              R"({"type": "sphere", "material": "m", "center": [0, 0, 0],
                                  "radius": 1.5})",
                              a);
    const Geometry g(s);
    for (const glm::dvec2 angles :
         {glm::dvec2(0.7, 0.4), glm::dvec2(1.3, 2.5), glm::dvec2(2.2, -1.9)}) {
        const double theta = angles.x, phi = angles.y;
        const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta));
        const glm::dvec3 thetaHat(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
                                  -std::sin(theta));
        const SurfaceHit hit = hitAt(g, Vec3f(r * n), Vec3f(4.0 * n));
        const double h = a * theta / kPi<double>;
        expectNear(hit.ns, glm::normalize((1 + h / r) * kPi<double> * r * n - a * thetaHat),
                   "theta " + std::to_string(theta));
    }
}

TEST_F(ShadingNormalMaps, AConstantHeightLeavesEveryNormal) {
    const Vec3f from(0.3f, 0.4f, 6);
    // Without the map, the same shapes give the normals a constant height must leave.
    const std::string shapes =
        std::string(kWideRectangle) +
        R"(, {"type": "sphere", "material": "m", "center": [3, 0, 0], "radius": 1},
           {"type": "instance", "object": "ball", "transform": [{"scale": [2, 2, 2]},
            {"translate": [-4, 0, 0]}]},
           {"type": "mesh", "material": "m", "positions": [[0, 2, 0], [2, 2, 0.4], [2, 4, 0.1],
            [0, 4, 0]], "faces": [[0, 1, 2, 3]]})";
    const std::string ball =
        R"({"ball": [{"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 1}]})";
    // Geometry keeps a reference to its scene: the scenes outlive it.
    const SceneDesc plainScene = scene("", shapes, 0.0, ball);
    const SceneDesc bumpedScene =
        scene(R"("displacement": {"texture": "height 0.3"})", shapes, 0.0, ball);
    const Geometry plain(plainScene), bumped(bumpedScene);
    for (const Vec3f p : {Vec3f(0.5f, 0.2f, 0), Vec3f(3.2f, 0.3f, 0.5f), Vec3f(-4.5f, 0.6f, 1),
                          Vec3f(1.1f, 2.9f, 0.2f)}) {
        const SurfaceHit want = hitAt(plain, p, from);
        const SurfaceHit got = hitAt(bumped, p, from);
        ASSERT_EQ(got.shape, want.shape);
        // The sphere's dp/du grows by 1 + h / r and keeps its normal; the flat faces have
        // dn/du = 0. (Interpolated vertex normals are not the surface's: moving along them
        // turns the normal, in pbrt-v4 as here.)
        expectNear(got.ns, Vec3<double>(want.ns), "shape " + std::to_string(want.shape));
    }
}

TEST_F(ShadingNormalMaps, TheFlatNormalMapColourIsTheIdentity) {
    const std::string shapes =
        std::string(kWideRectangle) +
        R"(, {"type": "sphere", "material": "m", "center": [3, 0, 0], "radius": 1},
           {"type": "disk", "material": "m", "center": [-3, 0, 0], "normal": [0.2, 0.1, 1]},
           {"type": "mesh", "material": "m", "positions": [[0, 2, 0], [2, 2, 0.4], [2, 4, 0.1],
            [0, 4, 0]], "normals": [[0, 0.3, 1], [0.3, 0, 1], [0, 0, 1], [-0.2, 0.1, 1]],
            "faces": [[0, 1, 2, 3]]})";
    const SceneDesc plainScene = scene("", shapes);
    const SceneDesc mappedScene = scene(R"("normal_map": {"texture": "flat"})", shapes);
    const Geometry plain(plainScene), mapped(mappedScene);
    const Vec3f from(0.3f, 0.4f, 6);
    for (const Vec3f p : {Vec3f(0.5f, 0.2f, 0), Vec3f(3.2f, 0.3f, 0.5f), Vec3f(-3.1f, 0.2f, 0),
                          Vec3f(1.1f, 2.9f, 0.2f)}) {
        const SurfaceHit want = hitAt(plain, p, from);
        const SurfaceHit got = hitAt(mapped, p, from);
        ASSERT_EQ(got.shape, want.shape);
        expectNear(got.ns, Vec3<double>(want.ns), "shape " + std::to_string(want.shape));
    }
}

// (0.75, 0.5, 0.9330127) is (sin 30 deg, 0, cos 30 deg) in the tangent frame: the normal turns
// by 30 degrees towards dp/du, on the rectangle (dp/du along +x) and on the sphere (dp/du
// along phi-hat).
TEST_F(ShadingNormalMaps, ATiltedNormalMapColourTurnsTheNormalByItsAngle) {
    const SceneDesc s = scene(R"("normal_map": {"texture": "tilted"})",
                              std::string(kWideRectangle) +
                                  R"(, {"type": "sphere", "material": "m", "center": [3, 0, 0],
                                        "radius": 1})");
    const Geometry g(s);
    const double t = glm::radians(30.0);
    const SurfaceHit flat = hitAt(g, Vec3f(0.4f, -0.3f, 0), Vec3f(0.5f, 0, 5));
    expectNear(flat.ns, glm::dvec3(std::sin(t), 0, std::cos(t)), "rectangle");
    const double phi = 0.6, theta = 1.1;
    const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                       std::cos(theta));
    const glm::dvec3 phiHat(-std::sin(phi), std::cos(phi), 0);
    const SurfaceHit round =
        hitAt(g, Vec3f(glm::dvec3(3, 0, 0) + n), Vec3f(glm::dvec3(3, 0, 0) + 3.0 * n));
    expectNear(round.ns, std::cos(t) * n + std::sin(t) * phiHat, "sphere");
    EXPECT_NEAR(std::acos(glm::dot(glm::dvec3(round.ns), n)), t, 1e-4);
}

TEST_F(ShadingNormalMaps, TheReaderRefusesWhatItCannotUse) {
    const auto error = [&](const std::string& maps) {
        return errorOf([&] { (void)scene(maps, kWideRectangle); });
    };
    EXPECT_THAT(
        error(R"("displacement": {"texture": "u ramp"}, "normal_map": {"texture": "flat"})"),
        HasSubstr("materials.m.normal_map: a material takes a displacement (a bump map) "
                  "or a normal_map, not both"));
    EXPECT_THAT(error(R"("displacement": 0.1)"),
                HasSubstr("materials.m.displacement: expected {\"texture\": name}"));
    EXPECT_THAT(error(R"("normal_map": {"texture": "nowhere"})"),
                HasSubstr("materials.m.normal_map.texture: unknown texture \"nowhere\""));
    // An 8-bit image decoded from sRGB (the default) would bend every normal.
    writeRgb8(dir_ / "normals.png", 1, 1, {0.5f, 0.5f, 1.0f});
    const auto png = [&](const std::string& space) {
        return errorOf([&] {
            (void)testing::sceneFromText(R"({
              "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0]},
              "lights": [{"type": "point", "position": [0, 0, 20], "intensity": 1}],
              "textures": {"n": {"type": "image", "file": ")" +
                                         (dir_ / "normals.png").string() + "\"" + space + R"(}},
              "materials": {"m": {"type": "lambert", "normal_map": {"texture": "n"}}},
              "shapes": [{"type": "rectangle", "material": "m"}]})");
        });
    };
    EXPECT_THAT(png(""), HasSubstr("materials.m.normal_map.texture: a normal map's image must be "
                                   "read with \"color_space\": \"linear\""));
    EXPECT_EQ(png(R"(, "color_space": "linear")"), "(accepted)");
}

}  // namespace
}  // namespace lamina::render
