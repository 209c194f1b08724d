// What each pbrt-v4 construct becomes in lamina's scene document (docs/interchange.md,
// "pbrt-v4"): the translated JSON compared exactly, the warnings of what was mapped, and the
// errors, with file and line, of what is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "lamina/geometry/geometry.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/render/perspective_camera.h"
#include "lamina/scene/mesh_files.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;

// A minimal scene around the lines under test: a camera and a light, so that the translated
// document also loads.
constexpr const char* kPrelude =
    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
    "LightSource \"point\" \"rgb I\" [1 1 1]\n";
constexpr int kPreludeLines = 4;

class PbrtTranslation : public lamina::testing::ScratchDirectoryTest {
  protected:
    ImportedScene import(const std::string& body, bool prelude = true) {
        file_ = write("s.pbrt", (prelude ? kPrelude : "") + body);
        return importScene(file_, dir_);
    }
    std::string importError(const std::string& body, bool prelude = true) {
        return errorOf([&] { import(body, prelude); });
    }
    /// "FILE:LINE" of line `n` of the body (after the prelude).
    std::string at(int n, bool prelude = true) const {
        return (dir_ / "s.pbrt").string() + ":" + std::to_string(n + (prelude ? kPreludeLines : 0));
    }
    /// Whether the translated document loads as a lamina scene.
    void expectLoads() {
        EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
    }
    std::filesystem::path file_;
};

TEST_F(PbrtTranslation, DefaultsArePbrtV4s) {
    const ImportedScene s = import("Shape \"sphere\"\n");
    EXPECT_EQ(s.format, SceneFormat::Pbrt);
    EXPECT_EQ(s.scene["film"], Json::parse(R"({"resolution": [1280, 720],
        "filter": {"type": "gaussian", "radius": 1.5}})"));
    EXPECT_EQ(s.scene["sampler"], Json::parse(R"({"type": "sobol", "spp": 16})"));
    EXPECT_EQ(s.scene["integrator"], Json::parse(R"({"type": "path", "max_depth": 5})"));
    EXPECT_EQ(s.scene["camera"], Json::parse(R"({"position": [0, 0, 0], "look_at": [0, 0, 1],
        "up": [0, 1, 0], "fov": 90, "handedness": "left"})"));
    EXPECT_EQ(s.scene["materials"]["pbrt_default"],
              Json::parse(R"({"type": "lambert", "reflectance": 0.5})"));
    EXPECT_EQ(s.scene["shapes"][0], Json::parse(R"({"type": "sphere", "center": [0, 0, 0],
        "radius": 1, "material": "pbrt_default"})"));
    EXPECT_EQ(s.scene["lights"][0], Json::parse(R"({"type": "point", "position": [0, 0, 0],
        "intensity": [1, 1, 1]})"));
    EXPECT_TRUE(s.warnings.empty());
    expectLoads();
}

TEST_F(PbrtTranslation, OptionsBlock) {
    const ImportedScene s = import(
        "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 32 \"string filename\" "
        "\"a.exr\"\nSampler \"halton\" \"integer pixelsamples\" 8\nIntegrator \"bdpt\" "
        "\"integer maxdepth\" 7 \"string lightsampler\" \"power\"\nPixelFilter \"triangle\"\n",
        false);
    EXPECT_EQ(s.scene["film"], Json::parse(R"({"resolution": [64, 32],
        "filter": {"type": "triangle", "radius": 2}})"));
    EXPECT_EQ(s.scene["sampler"], Json::parse(R"({"type": "sobol", "spp": 8})"));
    EXPECT_EQ(s.scene["integrator"],
              Json::parse(R"({"type": "bdpt", "max_depth": 7, "light_selection": "power"})"));
    const std::string f = file_.string();
    ASSERT_EQ(s.warnings.size(), 2u);
    EXPECT_EQ(s.warnings[0],
              f + ":1: the film's filename ignored: lamina writes the image named by -o");
    EXPECT_EQ(s.warnings[1], f + ":2: Sampler \"halton\" became lamina's Owen-scrambled Sobol "
                                 "sampler (same sample count)");
    const ImportedScene b = import(
        "PixelFilter \"box\"\nSampler \"stratified\" \"integer "
        "xsamples\" 2 \"integer ysamples\" 3\nIntegrator \"volpath\"\n"
        "PixelFilter \"gaussian\" \"float sigma\" 0.3\n",
        false);
    EXPECT_EQ(b.scene["film"]["filter"],
              Json::parse(R"({"type": "gaussian", "radius": 1.5, "sigma": 0.3})"));
    EXPECT_EQ(b.scene["sampler"]["spp"], 6);
    EXPECT_EQ(b.scene["integrator"]["type"], "path");
    // volpath is lamina's path tracer, which renders media as volpath does: no warning.
    EXPECT_EQ(b.warnings.back(), file_.string() +
                                     ":2: Sampler \"stratified\" became lamina's Owen-scrambled "
                                     "Sobol sampler with xsamples x ysamples = 6 samples per "
                                     "pixel");
    EXPECT_EQ(b.warnings[0], file_.string() +
                                 ":4: PixelFilter given again: this one replaces "
                                 "the one of line 1");
    EXPECT_EQ(import("Integrator \"lightpath\" \"integer maxdepth\" 3\n", false)
                  .scene["integrator"]["type"],
              "light");
    // Integrators whose converged image is lamina's: one warning each, what they become.
    const ImportedScene sppm = import(
        "Integrator \"sppm\" \"integer maxdepth\" 7 \"float radius\" 0.05 "
        "\"integer photonsperiteration\" 100000\n",
        false);
    EXPECT_EQ(sppm.scene["integrator"], Json::parse(R"({"type": "bdpt", "max_depth": 7})"));
    ASSERT_EQ(sppm.warnings.size(), 1u);
    EXPECT_EQ(sppm.warnings[0],
              file_.string() +
                  ":1: Integrator \"sppm\" became lamina's BDPT with the Sampler's sample count "
                  "(the image SPPM converges to, without the blur of its photon radius at a "
                  "finite count)");
    const ImportedScene mlt =
        import("Integrator \"mlt\" \"integer mutationsperpixel\" 64\n", false);
    EXPECT_EQ(mlt.scene["integrator"], Json::parse(R"({"type": "bdpt", "max_depth": 5})"));
    EXPECT_EQ(mlt.warnings.size(), 1u);
    for (const char* name : {"randomwalk", "simplepath"}) {
        const ImportedScene walk =
            import(std::string("Integrator \"") + name + "\" \"integer maxdepth\" 3\n", false);
        EXPECT_EQ(walk.scene["integrator"], Json::parse(R"({"type": "path", "max_depth": 3})"));
        EXPECT_EQ(walk.warnings.size(), 1u) << name;
    }
    // pbrt-v4's sobol: film positions from one global Sobol sequence, lamina's sobol-global.
    const ImportedScene g = import(
        "Sampler \"sobol\" \"integer pixelsamples\" 4 \"string randomization\" "
        "\"fastowen\"\n",
        false);
    EXPECT_EQ(g.scene["sampler"], Json::parse(R"({"type": "sobol-global", "spp": 4})"));
    ASSERT_EQ(g.warnings.size(), 1u);
    EXPECT_EQ(g.warnings[0], file_.string() +
                                 ":1: Sampler \"sobol\" became lamina's sobol-global sampler "
                                 "(pbrt-v4's global Sobol points; Owen-scrambled per pixel "
                                 "where pbrt-v4 scrambles per dimension; same sample count)");
}

TEST_F(PbrtTranslation, FovSpansTheShorterAxis) {
    const ImportedScene wide = import(
        "Film \"rgb\" \"integer xresolution\" 40 \"integer yresolution\" 20\n"
        "Camera \"perspective\" \"float fov\" 30\n",
        false);
    EXPECT_EQ(wide.scene["camera"]["fov"], 30.0);
    const ImportedScene tall = import(
        "Film \"rgb\" \"integer xresolution\" 20 \"integer yresolution\" 40\n"
        "Camera \"perspective\" \"float fov\" 30\n",
        false);
    // Horizontal 30 degrees: tan(v / 2) = tan(15 degrees) x 40 / 20.
    const double expected = 2 * std::atan(2 * std::tan(15.0 * M_PI / 180)) * 180 / M_PI;
    EXPECT_NEAR(tall.scene["camera"]["fov"].get<double>(), expected, 1e-12);
}

TEST_F(PbrtTranslation, MirroredCameraIsRightHanded) {
    // Exporters often write Scale -1 1 1 before LookAt to turn pbrt's left-handed camera
    // into a right-handed one.
    const ImportedScene s = import(
        "Scale -1 1 1\nLookAt 0 0 0  0 0 1  0 1 0\nCamera "
        "\"perspective\" \"float lensradius\" 0.1 "
        "\"float focaldistance\" 3\n",
        false);
    EXPECT_EQ(s.scene["camera"], Json::parse(R"({"position": [0, 0, 0], "look_at": [0, 0, 1],
        "up": [0, 1, 0], "fov": 90, "handedness": "right", "type": "thin_lens",
        "aperture_radius": 0.1, "focus_distance": 3})"));
    EXPECT_EQ(importError("Scale 1 2 1\nCamera \"perspective\"\n", false),
              (dir_ / "s.pbrt").string() +
                  ":2: the camera transform shears the view or scales its x and y axes "
                  "differently (pixels would not be square); lamina's camera takes rotations, "
                  "mirrors, uniform scales and a scale along the viewing axis");
    EXPECT_EQ(
        importError("Scale 1 1 0\nCamera \"perspective\"\n", false),
        (dir_ / "s.pbrt").string() + ":2: the camera transform is singular (it flattens the view)");
    EXPECT_EQ(importError("Camera \"spherical\"\n", false),
              at(1, false) +
                  ": Camera \"spherical\" is not supported (perspective, orthographic, "
                  "realistic); the spherical camera has no lamina equivalent");
}

// Exported camera matrices are rotations rounded to 6-8 digits: they load, with one warning,
// as the rotation they round.
TEST_F(PbrtTranslation, RoundedCameraRotationsLoad) {
    const ImportedScene s = import(
        "Transform [0.707107 0 -0.707107 0  0 1 0 0  0.707107 0 0.707107 0  0 0 -5 1]\n"
        "Camera \"perspective\" \"float fov\" 40\n",
        false);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0],
                ::testing::HasSubstr(":2: the camera transform is a rotation to within 3.1e-07"));
    EXPECT_THAT(s.warnings[0], ::testing::HasSubstr("(rounded digits): its nearest rotation"));
    EXPECT_NEAR(s.scene["camera"]["fov"].get<double>(), 40, 1e-4);
}

// A scale along the viewing axis alone: pbrt-v4 maps the camera-space direction (x, y, 1) by
// the transform and normalises it, so camera z stretched by 2 halves the image plane's tangent.
TEST_F(PbrtTranslation, AStretchOfTheViewingAxisNarrowsTheView) {
    const ImportedScene s =
        import("Scale 1 1 0.5\nCamera \"perspective\" \"float fov\" 60\n", false);
    const double expected = 2 * std::atan(std::tan(30.0 * M_PI / 180) / 2) * 180 / M_PI;
    EXPECT_NEAR(s.scene["camera"]["fov"].get<double>(), expected, 1e-12);
    EXPECT_TRUE(s.warnings.empty());
}

TEST(CameraHandedness, LeftHandedPutsUpCrossForwardOnTheRight) {
    CameraDesc desc;  // at the origin, looking along +z, +y up
    const PerspectiveCamera right(desc, 10, 10);
    desc.handedness = Handedness::Left;
    const PerspectiveCamera left(desc, 10, 10);
    // A ray through the image's right edge: lamina's default goes towards forward x up = -x,
    // the left-handed camera towards up x forward = +x; both keep +y at the top.
    EXPECT_LT(right.generateRay(9.5f, 5.0f, {0.5f, 0.5f}).direction.x, 0.0f);
    EXPECT_GT(left.generateRay(9.5f, 5.0f, {0.5f, 0.5f}).direction.x, 0.0f);
    EXPECT_GT(left.generateRay(5.0f, 0.5f, {0.5f, 0.5f}).direction.y, 0.0f);
    // The raster position of a direction is the inverse of generateRay.
    const auto ray = left.generateRay(2.25f, 7.5f, {0.5f, 0.5f});
    const auto raster = left.rasterPosition(ray.origin, ray.direction);
    ASSERT_TRUE(raster);
    EXPECT_NEAR(raster->x, 2.25f, 1e-4f);
    EXPECT_NEAR(raster->y, 7.5f, 1e-4f);
}

TEST_F(PbrtTranslation, ShapesAndTheirTransforms) {
    const ImportedScene s = import(
        "AttributeBegin\nTranslate 1 2 3\nScale 2 2 2\nReverseOrientation\nShape \"sphere\" "
        "\"float radius\" 0.5\nShape \"disk\" \"float radius\" 2 \"float height\" 1\nAttributeEnd\n"
        "Translate 0 0 5\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"normal N\" "
        "[0 0 1 0 0 1 0 0 1] \"point2 uv\" [0 0 1 0 0 1]\n"
        "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0] \"integer indices\" "
        "[0 1 2 3]\n");
    const Json& shapes = s.scene["shapes"];
    ASSERT_EQ(shapes.size(), 4u);
    EXPECT_EQ(shapes[0], Json::parse(R"({"type": "sphere", "center": [1, 2, 3], "radius": 1,
        "flip_normals": true, "material": "pbrt_default"})"));
    EXPECT_EQ(shapes[1], Json::parse(R"({"type": "disk", "center": [1, 2, 5], "normal": [0, 0, -1],
        "radius": 4, "material": "pbrt_default"})"));
    EXPECT_EQ(shapes[2], Json::parse(R"({"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0],
        [0, 1, 0]], "faces": [[0, 1, 2]], "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1]],
        "uvs": [[0, 0], [1, 0], [0, 1]], "material": "pbrt_default",
        "transform": [{"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1]}]})"));
    EXPECT_EQ(shapes[3]["faces"], Json::parse("[[0, 1, 3, 2]]"));
    expectLoads();
}

// The 16 numbers of a lamina "matrix" operation against `m`.
void expectMatrix(const Json& transform, const glm::dmat4& m) {
    ASSERT_EQ(transform.size(), 1u);
    const Json& rows = transform[0]["matrix"];
    ASSERT_EQ(rows.size(), 16u);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            EXPECT_NEAR(rows[std::size_t(4 * row + col)].get<double>(), m[col][row], 1e-12)
                << "row " << row << " column " << col;
}

// pbrt-v4's clipped spheres and disks and its cylinder (shapes.h, their constructors; shapes.cpp,
// Create): their parameters in their own frame, placed by the transform; zmin and zmax in
// either order, the sphere's clamped to its radius, phimax clamped to [0, 360]; the disk's
// height in the transform.
TEST_F(PbrtTranslation, ClippedQuadricsKeepPbrtV4sParametersInTheirFrame) {
    const ImportedScene s = import(
        "AttributeBegin\nTranslate 1 2 3\nRotate 90 1 0 0\nScale 2 2 2\n"
        "Shape \"sphere\" \"float radius\" 0.5 \"float zmin\" 0.8 \"float zmax\" -0.2 "
        "\"float phimax\" 400\n"
        "Shape \"cylinder\" \"float zmin\" 2 \"float zmax\" 0 \"float phimax\" 90\n"
        "ReverseOrientation\nShape \"disk\" \"float height\" 1 \"float innerradius\" 0.25 "
        "\"float phimax\" 180\nAttributeEnd\n"
        "Shape \"cylinder\"\n");
    const Json& shapes = s.scene["shapes"];
    ASSERT_EQ(shapes.size(), 4u);
    const glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
                         glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0)) *
                         glm::scale(glm::dmat4(1.0), glm::dvec3(2));
    // zmin 0.8 and zmax -0.2 swapped, then zmax clamped to the radius: the sphere's top is
    // whole (no z_max), and phimax 400 is 360 (no phi_max).
    EXPECT_EQ(shapes[0]["type"], "sphere");
    EXPECT_EQ(shapes[0]["radius"], 0.5);
    EXPECT_EQ(shapes[0]["z_min"], -0.2);
    EXPECT_FALSE(shapes[0].contains("z_max"));
    EXPECT_FALSE(shapes[0].contains("phi_max"));
    expectMatrix(shapes[0]["transform"], m);
    EXPECT_EQ(shapes[1]["type"], "cylinder");
    EXPECT_EQ(shapes[1]["radius"], 1);
    EXPECT_EQ(shapes[1]["z_min"], 0);
    EXPECT_EQ(shapes[1]["z_max"], 2);
    EXPECT_EQ(shapes[1]["phi_max"], 90);
    expectMatrix(shapes[1]["transform"], m);
    EXPECT_EQ(shapes[2]["type"], "disk");
    EXPECT_EQ(shapes[2]["inner_radius"], 0.25);
    EXPECT_EQ(shapes[2]["phi_max"], 180);
    EXPECT_EQ(shapes[2]["flip_normals"], true);  // ReverseOrientation
    expectMatrix(shapes[2]["transform"], glm::translate(m, glm::dvec3(0, 0, 1)));
    EXPECT_EQ(shapes[3], Json::parse(R"({"type": "cylinder", "radius": 1, "z_min": -1,
        "z_max": 1, "material": "pbrt_default"})"));
    EXPECT_TRUE(s.warnings.empty());
    expectLoads();
    // The lamina scene has pbrt-v4's surface and uv: the cylinder's object-space point at
    // phi = 45 degrees, z = 1 is hit from its axis, with u = 45 / 90 and v = (1 - 0) / (2 - 0),
    // and the disk's at phi = 90 degrees, rho = 0.625 (v = (1 - 0.625) / 0.75) faces -z in
    // its frame (ReverseOrientation) seen from there.
    const SceneDesc scene = loadScene(file_);
    const Geometry g(scene);
    const auto world = [&](const glm::dvec3& p) { return Vec3f(m * glm::dvec4(p, 1.0)); };
    const double c = std::sqrt(0.5);
    auto hit = g.intersect(world({0, 0, 1}), glm::normalize(world({c, c, 1}) - world({0, 0, 1})));
    ASSERT_TRUE(hit);
    EXPECT_LT(glm::length(hit->p - world({c, c, 1})), 1e-5f);
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-5f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-5f);
    hit = g.intersect(world({0, 0.625, 2}),
                      glm::normalize(world({0, 0.625, 0}) - world({0, 0.625, 2})));
    ASSERT_TRUE(hit);
    EXPECT_LT(glm::length(hit->p - world({0, 0.625, 1})), 1e-5f);
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-5f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-5f);
    EXPECT_NEAR(glm::dot(hit->ng, glm::normalize(world({0, 0, 0}) - world({0, 0, 1}))), 1.0f,
                1e-5f);
}

TEST_F(PbrtTranslation, ClippedQuadricsOfNoAreaAreOmittedAndHostileOnesRefused) {
    // pbrt-v4 renders nothing of a shape its clipping leaves no area: omitted, with a warning.
    const ImportedScene s = import(
        "Shape \"sphere\" \"float zmin\" 0.5 \"float zmax\" 0.5\n"
        "Shape \"cylinder\" \"float phimax\" 0\n"
        "Shape \"disk\" \"float innerradius\" 1\nShape \"sphere\"\n");
    ASSERT_EQ(s.scene["shapes"].size(), 1u);
    ASSERT_EQ(s.warnings.size(), 3u);
    EXPECT_EQ(s.warnings[0], at(1) +
                                 ": Shape \"sphere\" omitted: its zmin, zmax, phimax or "
                                 "innerradius leave it no area, and pbrt-v4 renders nothing of it");
    EXPECT_EQ(s.warnings[2].substr(0, at(3).size()), at(3));
    EXPECT_EQ(importError("Shape \"cylinder\" \"float radius\" -1\n"),
              at(1) + ": Shape \"cylinder\": \"radius\" must be > 0");
    EXPECT_EQ(importError("Shape \"sphere\" \"float radius\" 0 \"float phimax\" 90\n"),
              at(1) + ": Shape \"sphere\": \"radius\" must be > 0");
    EXPECT_EQ(importError("Shape \"disk\" \"float innerradius\" -0.5\n"),
              at(1) + ": Shape \"disk\": \"innerradius\" must be >= 0");
    EXPECT_EQ(importError("AttributeBegin\nAreaLightSource \"diffuse\"\nScale 1 1 3\n"
                          "Shape \"cylinder\"\nAttributeEnd\n"),
              at(4) +
                  ": Shape \"cylinder\" under a shear or an uneven scale is not supported when "
                  "it emits (lamina places it as an instance, and instances cannot emit)");
    // An emitter's power divides by the clipped area, phi_max r (z_max - z_min) in the world.
    const ImportedScene lit = import(
        "AreaLightSource \"diffuse\" \"float power\" 10\nScale 2 2 2\n"
        "Shape \"cylinder\" \"float phimax\" 180\n");
    const double area = kPi<double> * 1 * 2 * 4;
    EXPECT_NEAR(lit.scene["shapes"][0]["emission"]["radiance"].get<double>(),
                10 / (kPi<double> * area), 1e-12);
}

TEST_F(PbrtTranslation, MeshesAndPatches) {
    write("m.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float "
          "y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const ImportedScene s = import(
        "ReverseOrientation\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
        "\"normal N\" [0 0 1 0 0 1 0 0 1]\nShape \"plymesh\" \"string filename\" \"m.ply\"\n"
        "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0]\n"
        "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 1]\n");
    const Json& shapes = s.scene["shapes"];
    // ReverseOrientation: the winding reversed and the normals negated.
    EXPECT_EQ(shapes[0]["faces"], Json::parse("[[2, 1, 0]]"));
    EXPECT_EQ(shapes[0]["normals"],
              Json::parse("[[-0.0, -0.0, -1], [-0.0, -0.0, -1], [-0.0, -0.0, -1]]"));
    EXPECT_EQ(shapes[1], Json::parse(R"({"type": "ply", "file": "m.ply",
        "material": "pbrt_default"})"));
    // p00, p10, p01, p11 -> the polygon p00 p10 p11 p01, reversed.
    EXPECT_EQ(shapes[2]["faces"], Json::parse("[[2, 3, 1, 0]]"));
    ASSERT_EQ(s.warnings.size(), 2u);
    EXPECT_EQ(s.warnings[0], at(3) +
                                 ": ReverseOrientation on an opaque plymesh ignored: it "
                                 "changes nothing there");
    EXPECT_EQ(s.warnings[1], at(5) + ": bilinearmesh: a non-planar patch became two triangles");
    expectLoads();
}

// pbrt-v4's curves: Bezier (cubic, quadratic raised) and B-spline strands become one-strand
// `curves` shapes of cubic Bezier segments; the hair material keeps its parameters.
TEST_F(PbrtTranslation, CurvesAndHair) {
    const ImportedScene s = import(
        "Material \"hair\" \"float eumelanin\" 0.8 \"float beta_m\" 0.2\n"
        "Shape \"curve\" \"point3 P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"string type\" "
        "\"cylinder\" \"float width0\" 0.2 \"float width1\" 0.1 \"integer splitdepth\" 2\n"
        "Shape \"curve\" \"point3 P\" [0 0 0 3 0 0 3 3 0] \"integer degree\" 2\n"
        "Shape \"curve\" \"point3 P\" [0 0 0 6 0 0 6 6 0 0 6 0 0 0 6] \"string basis\" "
        "\"bspline\"\n"
        "Material \"hair\" \"rgb sigma_a\" [0.1 0.2 0.3] \"rgb reflectance\" [0.5 0.5 0.5]\n"
        "Shape \"curve\" \"point3 P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"string type\" \"ribbon\" "
        "\"normal N\" [0 0 1 0 0 1]\n");
    // The second and third curves (flat, of width 1 and one material) are one shape of two
    // strands, as a hair file's curves become one.
    const Json& shapes = s.scene["shapes"];
    ASSERT_EQ(shapes.size(), 3u);
    EXPECT_EQ(shapes[0]["type"], "curves");
    EXPECT_EQ(shapes[0]["curve"], "cylinder");
    EXPECT_EQ(shapes[0]["strands"], Json::parse("[[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]]"));
    EXPECT_EQ(shapes[0]["width0"], 0.2);
    EXPECT_EQ(shapes[0]["width1"], 0.1);
    // pbrt-v4's default type is flat; a quadratic segment raised to a cubic.
    EXPECT_EQ(shapes[1]["curve"], "flat");
    EXPECT_EQ(shapes[1]["width"], 1.0);
    EXPECT_EQ(shapes[1]["strands"][0], Json::parse("[[0, 0, 0], [2, 0, 0], [3, 1, 0], [3, 3, 0]]"));
    // Five B-spline points: two segments, seven Bezier points, ends shared.
    ASSERT_EQ(shapes[1]["strands"].size(), 2u);
    const Json& b = shapes[1]["strands"][1];
    ASSERT_EQ(b.size(), 7u);
    EXPECT_EQ(b[0], Json::parse("[5, 1, 0]"));  // (p0 + 4 p1 + p2) / 6
    EXPECT_EQ(b[3], Json::parse("[5, 5, 0]"));  // (p1 + 4 p2 + p3) / 6
    const Json& m = s.scene["materials"];
    const std::string first = shapes[0]["material"], second = shapes[2]["material"];
    EXPECT_EQ(m[first], Json::parse(R"({"type": "hair", "eumelanin": 0.8, "pheomelanin": 0.0,
        "eta": 1.55, "beta_m": 0.2, "beta_n": 0.3, "alpha": 2.0})"));
    EXPECT_EQ(m[second]["sigma_a"], Json::parse("[0.1, 0.2, 0.3]"));
    EXPECT_FALSE(m[second].contains("reflectance"));
    const std::vector<std::string> expected = {
        at(2) +
            ": curve \"cylinder\" became a round tube (pbrt-v4 draws a ribbon facing the ray "
            "with a tube's normal): the same look, and light that crosses the fibre leaves it "
            "from the far side (said once for the file)",
        at(2) +
            ": curve: \"splitdepth\" ignored (Embree intersects the curve itself, without "
            "splitting it) (said once for the file)",
        at(3) +
            ": curve \"flat\": lamina's ribbon facing the ray is shaded with a tube's normal "
            "(pbrt-v4's with the ribbon's) (said once for the file)",
        at(5) +
            ": hair: \"reflectance\" ignored, as pbrt-v4 does: the absorption is given by an "
            "earlier parameter (sigma_a, then reflectance, then melanin)",
        at(6) +
            ": curve \"ribbon\" became a flat ribbon facing the ray: its normals \"N\" "
            "ignored (said once for the file)"};
    EXPECT_EQ(s.warnings, expected);
    expectLoads();
    EXPECT_EQ(importError("Shape \"curve\" \"point3 P\" [0 0 0 1 0 0 1 1 0]\n"),
              at(1) + ": curve: 3 control points; a degree 3 Bezier curve takes 4 + n * 3");
    EXPECT_EQ(importError("AreaLightSource \"diffuse\"\nShape \"curve\" \"point3 P\" "
                          "[0 0 0 1 0 0 1 1 0 0 1 0]\n"),
              at(2) +
                  ": an emitting Shape \"curve\" is not supported (lamina's curves do not "
                  "emit)");
}

TEST_F(PbrtTranslation, UnsupportedShapesAndParametersAreRefused) {
    EXPECT_EQ(importError("\nShape \"paraboloid\"\n"),
              at(2) +
                  ": Shape \"paraboloid\" is not supported (lamina reads sphere, disk, "
                  "cylinder, trianglemesh, plymesh, bilinearmesh, loopsubdiv and curve)");
    EXPECT_EQ(importError("Shape \"sphere\" \"float wobble\" 0.5\n"),
              at(1) + ": Shape \"sphere\": parameter \"float wobble\" is not supported");
    EXPECT_EQ(importError("Shape \"sphere\" \"integer radius\" 2\n"),
              at(1) +
                  ": Shape \"sphere\": parameter \"integer radius\" has the wrong type: "
                  "expected float");
    EXPECT_EQ(importError("Shape \"plymesh\" \"string filename\" \"absent.ply\"\n"),
              at(1) +
                  ": Shape \"plymesh\": parameter \"string filename\" \"absent.ply\": no "
                  "such file");
    EXPECT_EQ(importError("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 1]\n"),
              at(1) + ": Shape \"trianglemesh\": no \"integer indices\"");
    EXPECT_EQ(importError("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
                          "\"integer indices\" [0 1 3]\n"),
              at(1) +
                  ": Shape \"trianglemesh\": parameter \"integer indices\" has an index "
                  "outside [0, 3)");
    EXPECT_EQ(importError("NamedMaterial \"nothing\"\nShape \"sphere\"\n"),
              at(1) + ": no material named \"nothing\"");
}

TEST_F(PbrtTranslation, AreaLights) {
    const ImportedScene s = import(
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 2 3] \"float scale\" 2 "
        "\"bool twosided\" true\nShape \"sphere\"\nAttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"float power\" 10\nShape \"disk\"\n"
        "AttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"blackbody L\" 3000\nShape \"sphere\"\n"
        "AttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"spectrum L\" \"stdillum-F11\"\n"
        "Shape \"sphere\"\nAttributeEnd\n");
    const Json& shapes = s.scene["shapes"];
    EXPECT_EQ(shapes[0]["emission"], Json::parse(R"({"radiance": [2, 4, 6], "two_sided": true})"));
    // pbrt-v4's power: radiance = power / (pi area) for a one-sided disk of radius 1.
    EXPECT_NEAR(shapes[1]["emission"]["radiance"].get<double>(), 10 / (M_PI * M_PI), 1e-12);
    EXPECT_EQ(shapes[2]["emission"],
              Json::parse(R"({"radiance": {"blackbody": 3000, "scale": 1}})"));
    EXPECT_EQ(shapes[3]["emission"],
              Json::parse(R"({"radiance": {"illuminant": "F11", "scale": 1}})"));
    expectLoads();
    EXPECT_EQ(importError("AreaLightSource \"diffuse\" \"string filename\" \"e.exr\"\n"
                          "Shape \"sphere\"\n"),
              at(1) +
                  ": AreaLightSource \"diffuse\": an emission image (filename) is not "
                  "supported");
    EXPECT_EQ(importError("AreaLightSource \"glow\"\nShape \"sphere\"\n"),
              at(1) + ": AreaLightSource \"glow\" is not supported (lamina reads \"diffuse\")");
}

TEST_F(PbrtTranslation, TabulatedEmissionIsNormalisedToItsLuminance) {
    // pbrt-v4 divides a light's spectrum by its luminance: "scale" nits whatever the values.
    const ImportedScene s = import(
        "AreaLightSource \"diffuse\" \"spectrum L\" [400 10 700 30] "
        "\"float scale\" 2\nShape \"sphere\"\n");
    const Json& radiance = s.scene["shapes"][0]["emission"]["radiance"];
    // Closed with zeros outside 400-700 nm, where pbrt's spectrum is 0.
    std::vector<double> nm, values;
    for (const Json& pair : radiance["spectrum"]) {
        nm.push_back(pair[0].get<double>());
        values.push_back(pair[1].get<double>());
    }
    const std::vector<double> expectedNm = {360, 399.999, 400, 700, 700.001, 830};
    const std::vector<double> expectedValues = {0, 0, 10, 30, 0, 0};
    ASSERT_EQ(nm.size(), expectedNm.size());
    for (std::size_t i = 0; i < nm.size(); ++i) {
        EXPECT_NEAR(nm[i], expectedNm[i], 1e-9);
        EXPECT_EQ(values[i], expectedValues[i]);
    }
    const EmissionSpectrum e =
        EmissionSpectrum::tabulated(nm, values, radiance["scale"].get<double>(), "test");
    const double y =
        integrateAgainstCmf([&](double lambda) { return e(lambda); }).y / cieYIntegral();
    EXPECT_NEAR(y, 2.0, 1e-9);
}

TEST_F(PbrtTranslation, Lights) {
    const ImportedScene s = import(
        "Translate 0 1 0\nLightSource \"spot\" \"point3 from\" [0 0 0] \"point3 to\" [0 0 1] "
        "\"float coneangle\" 40 \"float conedeltaangle\" 10 \"blackbody I\" 5000\n"
        "LightSource \"distant\" \"point3 from\" [0 0 0] \"point3 to\" [0 -1 0] \"rgb L\" "
        "[1 1 1] \"float illuminance\" 3\n"
        "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
        "LightSource \"point\" \"float power\" 100\n");
    const Json& lights = s.scene["lights"];
    EXPECT_EQ(lights[1], Json::parse(R"({"type": "spot", "position": [0, 1, 0],
        "look_at": [0, 1, 1], "intensity": {"blackbody": 5000, "scale": 1}, "cone_angle": 40,
        "falloff_start": 30})"));
    EXPECT_EQ(lights[2], Json::parse(R"({"type": "directional", "direction": [0, -1, 0],
        "irradiance": [3, 3, 3]})"));
    EXPECT_EQ(lights[3], Json::parse(R"({"type": "environment", "radiance": [0.5, 0.5, 0.5]})"));
    EXPECT_NEAR(lights[4]["intensity"].get<double>(), 100 / (4 * M_PI), 1e-12);
    EXPECT_EQ(lights[4]["position"], Json::parse("[0, 1, 0]"));
    expectLoads();
    EXPECT_EQ(importError("LightSource \"goniometric\"\n"),
              at(1) +
                  ": LightSource \"goniometric\" is not supported (point, spot, distant, "
                  "infinite)");
}

TEST_F(PbrtTranslation, EnvironmentImagesAreOctahedral) {
    write("sky.exr", "not read by the importer");
    const ImportedScene s = import(
        "Rotate 90 1 0 0\nLightSource \"infinite\" \"string filename\" "
        "\"sky.exr\" \"float scale\" 2\n");
    EXPECT_EQ(s.scene["lights"][1],
              Json::parse(R"({"type": "environment", "file": "sky.exr", "scale": 2,
        "mapping": "equal_area_octahedral",
        "transform": [{"matrix": [1, 0, 0, 0, 0, 6.123233995736766e-17, -1, 0,
                                  0, 1, 6.123233995736766e-17, 0, 0, 0, 0, 1]}]})"));
    const ImportedScene mirrored =
        import("Scale -1 1 1\nLightSource \"infinite\" \"string filename\" \"sky.exr\"\n");
    EXPECT_EQ(mirrored.scene["lights"][1]["transform"],
              Json::parse(R"([{"matrix": [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}])"));
    // pbrt-v4 normalises the light-space direction: a uniform scale changes nothing.
    const ImportedScene scaled =
        import("Scale 2 2 2\nLightSource \"infinite\" \"string filename\" \"sky.exr\"\n");
    EXPECT_FALSE(scaled.scene["lights"][1].contains("transform"));
    EXPECT_EQ(
        importError("Scale 1 2 1\nLightSource \"infinite\" \"string filename\" \"sky.exr\"\n"),
        at(2) +
            ": infinite: only rotations, reflections and uniform scales may orient an environment "
            "image (a shear or an uneven scale was given)");
    // A rotation written with 6 digits, as exporters write one: its nearest rotation, with a
    // warning.
    const ImportedScene rounded = import(
        "Transform [0.866025 0.5 0 0  -0.5 0.866025 0 0  0 0 1 0  0 0 0 1]\n"
        "LightSource \"infinite\" \"string filename\" \"sky.exr\"\n");
    ASSERT_EQ(rounded.warnings.size(), 1u);
    EXPECT_THAT(rounded.warnings[0],
                ::testing::HasSubstr("infinite: the light's transform is a rotation to within"));
    const Json& rows = rounded.scene["lights"][1]["transform"][0]["matrix"];
    glm::dmat3 r;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            r[col][row] = rows[std::size_t(row * 4 + col)].get<double>();
    const glm::dmat3 rtr = glm::transpose(r) * r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(rtr[i][j], i == j ? 1.0 : 0.0, 1e-14);
    EXPECT_NEAR(r[0][0], std::cos(M_PI / 6), 1e-6);
}

// pbrt-v4's coated walk stops at maxdepth 10; lamina's would not, so the importer writes the
// cap and says so.
std::string coatedWarning(const std::string& type) {
    return type +
           " became lamina's coated with max_depth 10 (pbrt-v4's maxdepth: its random walk "
           "stops there, which darkens bright bases; remove max_depth for lamina's unbiased "
           "walk, which ends by Russian roulette)";
}

TEST_F(PbrtTranslation, Materials) {
    std::string shapes;
    for (const char* name : {"gold", "mirror", "glass", "thin", "paint", "car", "leaf", "both",
                             "grey-mirror", "copper"})
        shapes += std::string("NamedMaterial \"") + name + "\"\nShape \"sphere\"\n";
    const ImportedScene t = import(
        "MakeNamedMaterial \"gold\" \"string type\" \"conductor\" \"spectrum eta\" "
        "\"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" \"float roughness\" 0.25\n"
        "MakeNamedMaterial \"mirror\" \"string type\" \"conductor\" \"rgb reflectance\" "
        "[0.64 0 0.25]\n"
        "MakeNamedMaterial \"glass\" \"string type\" \"dielectric\" \"spectrum eta\" "
        "\"glass-F11\" \"float uroughness\" 0.04 \"float vroughness\" 0.09\n"
        "MakeNamedMaterial \"thin\" \"string type\" \"thindielectric\" \"float eta\" 1.33\n"
        "MakeNamedMaterial \"paint\" \"string type\" \"coateddiffuse\" \"rgb reflectance\" "
        "[0.5 0.2 0.1] \"float roughness\" 0.0\n"
        "MakeNamedMaterial \"car\" \"string type\" \"coatedconductor\" \"float interface.eta\" 2 "
        "\"float conductor.eta\" 0.4 \"float conductor.k\" 6 \"float thickness\" 0.1\n"
        "MakeNamedMaterial \"leaf\" \"string type\" \"diffusetransmission\" \"float scale\" 2\n"
        "MakeNamedMaterial \"both\" \"string type\" \"mix\" \"string materials\" [\"gold\" "
        "\"paint\"] \"float amount\" 0.25\n"
        "MakeNamedMaterial \"unused\" \"string type\" \"hair\"\n"
        "MakeNamedMaterial \"grey-mirror\" \"string type\" \"conductor\" \"float reflectance\" "
        "0.64\n"
        "MakeNamedMaterial \"copper\" \"string type\" \"conductor\" \"rgb eta\" [0.2 0.92 1.1] "
        "\"rgb k\" [3.9 2.45 2.14] \"float roughness\" 0.05 \"bool remaproughness\" false\n" +
        shapes);
    const Json& m = t.scene["materials"];
    EXPECT_EQ(m["gold"], Json::parse(R"({"type": "conductor", "material": "Au", "alpha": 0.5})"));
    // pbrt-v4's reflectance form: eta 1, k = 2 sqrt(r) / sqrt(1 - r) at each wavelength, of
    // the colour upsampled as a reflectance: a spectrum every 5 nm over 360-830 nm.
    EXPECT_EQ(m["mirror"]["eta"], 1.0);
    const Json& k = m["mirror"]["k"];
    ASSERT_EQ(k.size(), 95u);
    const RgbSpectrum r(Rgb<double>(0.64, 0, 0.25), RgbSpectrumKind::Reflectance);
    for (std::size_t i = 0; i < k.size(); i += 7) {
        const double nm = 360.0 + 5.0 * double(i), ri = r(nm);
        EXPECT_EQ(k[i][0].get<double>(), nm);
        EXPECT_NEAR(k[i][1].get<double>(), 2 * std::sqrt(ri) / std::sqrt(1 - ri), 1e-12) << nm;
    }
    // A grey reflectance stays numbers, k = 2 sqrt(r) / sqrt(1 - r).
    EXPECT_NEAR(m["grey-mirror"]["k"].get<double>(), 2 * 0.8 / 0.6, 1e-12);
    // rgb eta and k are kept as triples, without a warning (lamina upsamples them as pbrt-v4
    // does, spectrum_context.h).
    EXPECT_EQ(m["copper"], Json::parse(R"({"type": "conductor", "eta": [0.2, 0.92, 1.1],
        "k": [3.9, 2.45, 2.14], "alpha": 0.05})"));
    EXPECT_EQ(m["glass"]["ior"], Json::parse(R"({"sellmeier": {
        "b": [1.73759695, 0.313747346, 1.89878101], "c": [0.013188707, 0.0623068142, 155.23629]}})"));
    EXPECT_NEAR(m["glass"]["alpha_x"].get<double>(), 0.2, 1e-15);
    EXPECT_NEAR(m["glass"]["alpha_y"].get<double>(), 0.3, 1e-15);
    EXPECT_EQ(m["thin"], Json::parse(R"({"type": "thin_dielectric", "ior": 1.33})"));
    EXPECT_EQ(m["paint"], Json::parse(R"({"type": "coated", "ior": 1.5, "thickness": 0.01,
        "albedo": 0, "g": 0, "max_depth": 10, "samples": 1,
        "base": {"type": "lambert", "reflectance": [0.5, 0.2, 0.1]}})"));
    // The conductor's eta and k divided by the coat's index, as pbrt-v4 does.
    EXPECT_EQ(m["car"], Json::parse(R"({"type": "coated", "ior": 2, "thickness": 0.1,
        "albedo": 0, "g": 0, "max_depth": 10, "samples": 1,
        "base": {"type": "conductor", "eta": 0.2, "k": 3}})"));
    EXPECT_EQ(m["leaf"], Json::parse(R"({"type": "diffuse_transmission", "reflectance": 0.5,
        "transmittance": 0.5})"));
    EXPECT_EQ(m["both"]["type"], "mix");
    EXPECT_EQ(m["both"]["weight"], 0.25);
    EXPECT_EQ(m["both"]["a"], m["gold"]);
    EXPECT_EQ(m["both"]["b"], m["paint"]);
    EXPECT_FALSE(m.contains("unused"));
    const std::vector<std::string> expected = {
        at(1) +
            ": metal-Au-eta/k became lamina's conductor \"Au\": lamina's measured table, not "
            "pbrt-v4's (colours may differ slightly)",
        at(3) + ": glass-F11 became the Sellmeier formula of SCHOTT SF11 (pbrt-v4 tabulates it)",
        at(3) +
            ": anisotropic roughness became alpha_x along the surface's u tangent and "
            "alpha_y along v",
        at(5) + ": " + coatedWarning("coateddiffuse"),
        at(6) + ": " + coatedWarning("coatedconductor"),
        at(9) + ": material \"unused\" is used by no shape: not translated"};
    EXPECT_EQ(t.warnings, expected);
}

TEST_F(PbrtTranslation, MaterialErrors) {
    // pbrt-v3's plastic, which pbrt-v4 has not either.
    EXPECT_EQ(importError("Material \"plastic\"\nShape \"sphere\"\n"),
              at(1) +
                  ": material \"plastic\" is not supported (lamina reads diffuse, conductor, "
                  "dielectric, thindielectric, coateddiffuse, coatedconductor, "
                  "diffusetransmission, measured, hair, subsurface, mix and interface)");
    EXPECT_EQ(importError("Material \"conductor\" \"spectrum eta\" \"metal-CuZn-eta\" "
                          "\"spectrum k\" \"metal-CuZn-k\"\nShape \"sphere\"\n"),
              at(1) +
                  ": Material \"conductor\": parameter \"spectrum eta\" \"metal-CuZn\" has "
                  "no lamina equivalent (lamina knows metal-Ag, Al, Au and Cu)");
    EXPECT_EQ(importError("Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\"\n"
                          "Shape \"sphere\"\n"),
              at(1) +
                  ": Material \"conductor\": parameter \"spectrum eta\" and the other of eta "
                  "and k must name the same metal-* spectra (lamina has measured eta and k "
                  "only together)");
    EXPECT_EQ(importError("Material \"diffuse\" \"float sigma\" 3\nShape \"sphere\"\n"),
              at(1) + ": Material \"diffuse\": parameter \"float sigma\" is not supported");
    EXPECT_EQ(importError("Material \"dielectric\" \"spectrum eta\" [400 1.5 700 1.4]\n"
                          "Shape \"sphere\"\n"),
              at(1) +
                  ": Material \"dielectric\": parameter \"spectrum eta\" a tabulated, "
                  "wavelength-dependent eta is not supported (give a float or a named "
                  "glass-* spectrum)");
}

TEST_F(PbrtTranslation, InterfaceShapesThatSeparateNoMediaAreOmittedWithAWarning) {
    const ImportedScene s = import("Material \"interface\"\nShape \"sphere\"\n");
    EXPECT_TRUE(s.scene["shapes"].empty());
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], at(2) +
                                 ": Shape \"sphere\" with the \"interface\" material separates "
                                 "no media: omitted (pbrt-v4's rays pass through it)");
}

// MakeNamedMedium "homogeneous" becomes a lamina medium with pbrt-v4's defaults (sigma_a and
// sigma_s 1, scale 1, g 0); MediumInterface makes a shape a boundary ("interior" the inside,
// "exterior" the outside, "" vacuum), an interface material the lamina "interface"; the
// camera sits in the outside medium of its time.
TEST_F(PbrtTranslation, HomogeneousMediaAndTheirBoundaries) {
    const ImportedScene s = import(
        "MediumInterface \"\" \"fog\"\n"
        "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "LightSource \"point\" \"rgb I\" [1 1 1]\n"
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "MakeNamedMedium \"ruby\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [.01 .2 .5]\n"
        "  \"spectrum sigma_s\" [300 0.25 800 0.25] \"float scale\" 2 \"float g\" -0.3\n"
        "  \"rgb Le\" [1 0.5 0.25] \"float Lescale\" 4\n"
        "MakeNamedMedium \"milk\" \"string type\" \"homogeneous\" \"string preset\" "
        "\"Wholemilk\"\n"
        "MakeNamedMedium \"unused\" \"string type\" \"nanovdb\"\n"
        "AttributeBegin\nMediumInterface \"ruby\" \"fog\"\nMaterial \"dielectric\"\n"
        "Shape \"sphere\"\nAttributeEnd\n"
        "AttributeBegin\nMediumInterface \"milk\" \"fog\"\nMaterial \"\"\n"
        "Shape \"disk\"\nAttributeEnd\n",
        false);
    EXPECT_EQ(s.scene["media"], Json::parse(R"({
        "fog": {"type": "homogeneous", "sigma_a": 1.0, "sigma_s": 1.0, "scale": 1.0, "g": 0.0},
        "ruby": {"type": "homogeneous", "sigma_a": [0.01, 0.2, 0.5], "sigma_s": 0.25,
                 "scale": 2.0, "g": -0.3, "Le": [4.0, 2.0, 1.0]},
        "milk": {"type": "homogeneous", "sigma_a": [0.0011, 0.0024, 0.014],
                 "sigma_s": [2.55, 3.21, 3.77], "scale": 1.0, "g": 0.0}})"));
    EXPECT_EQ(s.scene["camera"]["medium"], "fog");
    ASSERT_EQ(s.scene["shapes"].size(), 2u);
    EXPECT_EQ(s.scene["shapes"][0]["interior"], "ruby");
    EXPECT_EQ(s.scene["shapes"][0]["exterior"], "fog");
    EXPECT_NE(s.scene["shapes"][0]["material"], "interface");
    EXPECT_EQ(s.scene["shapes"][1]["material"], "interface");
    EXPECT_EQ(s.scene["shapes"][1]["interior"], "milk");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], at(11, false) +
                                 ": medium \"unused\" bounds no shape and holds no camera: not "
                                 "translated");
    expectLoads();
}

// pbrt-v4's path integrator renders a scene as if it had no media; lamina's path tracer renders
// them, as volpath does: a warning says so (volpath itself maps to lamina's path silently).
TEST_F(PbrtTranslation, ThePathIntegratorOfASceneWithMediaWarns) {
    const ImportedScene s = import(
        "Integrator \"path\"\nMediumInterface \"\" \"fog\"\nCamera \"perspective\"\n"
        "WorldBegin\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "LightSource \"point\"\n",
        false);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], at(1, false) +
                                 ": Integrator \"path\" of a scene with media: pbrt-v4's path "
                                 "integrator renders it as if there were none, lamina's path "
                                 "tracer with them (as volpath)");
}

TEST_F(PbrtTranslation, MediaErrorsNameFileAndLine) {
    const std::string box =
        "AttributeBegin\nMediumInterface \"m\" \"\"\nMaterial \"interface\"\n"
        "Shape \"sphere\"\nAttributeEnd\n";
    EXPECT_EQ(importError("MakeNamedMedium \"m\" \"string type\" \"nanovdb\"\n" + box),
              at(1) + ": MakeNamedMedium \"m\": nanovdb needs a \"string filename\"");
    EXPECT_EQ(importError(box), at(2) +
                                    ": MediumInterface: no medium \"m\" (MakeNamedMedium "
                                    "defines one; \"\" is vacuum)");
    EXPECT_EQ(
        importError("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"float g\" 1\n" + box),
        at(1) +
            ": MakeNamedMedium \"m\": parameter \"float g\" must lie in "
            "(-1, 1): lamina's Henyey-Greenstein phase function has no delta limit");
    EXPECT_EQ(importError("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" "
                          "\"spectrum sigma_a\" [400 0.1 700 0.2]\n" +
                          box),
              at(1) +
                  ": MakeNamedMedium \"m\": parameter \"spectrum sigma_a\" "
                  "varies with wavelength: lamina's media take a number or an rgb triple "
                  "(give \"rgb sigma_a\")");
    EXPECT_EQ(importError("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" "
                          "\"rgb sigma_s\" [1 -1 1]\n" +
                          box),
              at(1) +
                  ": MakeNamedMedium \"m\": parameter \"rgb sigma_s\" must be "
                  "finite and >= 0");
    EXPECT_EQ(importError("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" "
                          "\"float density\" 2\n" +
                          box),
              at(1) +
                  ": MakeNamedMedium \"m\": parameter \"float density\" is not "
                  "supported");
}

TEST_F(PbrtTranslation, Textures) {
    write("wood.png", "not read by the importer");
    const ImportedScene s = import(
        "Texture \"wood\" \"spectrum\" \"imagemap\" \"string filename\" \"wood.png\" "
        "\"float uscale\" 2 \"float vscale\" 3 \"float scale\" 0.5\n"
        "Texture \"mask\" \"float\" \"imagemap\" \"string filename\" \"wood.png\" "
        "\"string encoding\" \"linear\" \"bool invert\" true\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [1 0 0] \"float tex2\" 0.5\n"
        "Texture \"both\" \"spectrum\" \"mix\" \"texture tex1\" \"wood\" \"texture tex2\" "
        "\"checks\" \"texture amount\" \"mask\"\n"
        "Texture \"half\" \"spectrum\" \"scale\" \"texture tex\" \"both\" \"float scale\" 0.5\n"
        "Material \"diffuse\" \"texture reflectance\" \"half\"\n"
        "Shape \"sphere\" \"texture alpha\" \"mask\"\nShape \"disk\" \"float alpha\" 0.5\n");
    const Json& t = s.scene["textures"];
    EXPECT_EQ(t["wood (image)"], Json::parse(R"j({"type": "image", "file": "wood.png",
        "color_space": "srgb", "scale": [2, 3]})j"));
    EXPECT_EQ(t["wood"],
              Json::parse(R"j({"type": "scale", "texture": "wood (image)", "scale": 0.5})j"));
    EXPECT_EQ(t["mask (float)"], Json::parse(R"j({"type": "image", "file": "wood.png",
        "color_space": "linear", "scale": [1, 1], "invert": true})j"));
    EXPECT_EQ(t["checks"], Json::parse(R"j({"type": "checkerboard", "a": [1, 0, 0], "b": 0.5,
        "scale": [1, 1]})j"));
    EXPECT_EQ(t["both"], Json::parse(R"j({"type": "mix", "a": "wood", "b": "checks",
        "amount": "mask (float)"})j"));
    EXPECT_EQ(t["half"], Json::parse(R"j({"type": "scale", "texture": "both", "scale": 0.5})j"));
    EXPECT_EQ(s.scene["materials"]["pbrt_material_1"],
              Json::parse(R"j({"type": "lambert", "reflectance": {"texture": "half"}})j"));
    EXPECT_EQ(s.scene["shapes"][0]["alpha"], Json::parse(R"j({"texture": "mask (float)"})j"));
    EXPECT_EQ(s.scene["shapes"][1]["alpha"], 0.5);
    EXPECT_EQ(importError("Texture \"n\" \"spectrum\" \"bilerp\"\nMaterial \"diffuse\" "
                          "\"texture reflectance\" \"n\"\nShape \"sphere\"\n"),
              at(1) +
                  ": texture \"bilerp\" is not supported (lamina reads imagemap, constant, "
                  "checkerboard, dots, fbm, wrinkled, windy, marble, scale, mix and directionmix)");
    EXPECT_EQ(importError("Material \"diffuse\" \"texture reflectance\" \"none\"\n"
                          "Shape \"sphere\"\n"),
              at(1) + ": no spectrum texture named \"none\"");
    EXPECT_EQ(importError("AreaLightSource \"diffuse\"\nShape \"sphere\" \"float alpha\" 0.5\n"),
              at(2) + ": alpha on an emitting shape is not supported");
}

TEST_F(PbrtTranslation, ObjectsBecomeInstances) {
    const ImportedScene s = import(
        "ObjectBegin \"tri\"\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n"
        "ObjectEnd\nObjectBegin \"never\"\nShape \"sphere\"\nObjectEnd\n"
        "Translate 0 0 4\nObjectInstance \"tri\"\nTranslate 1 0 0\nObjectInstance \"tri\"\n");
    EXPECT_EQ(s.scene["objects"], Json::parse(R"({"tri": [{"type": "mesh",
        "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]],
        "material": "pbrt_default"}]})"));
    EXPECT_EQ(s.scene["shapes"], Json::parse(R"([
        {"type": "instance", "object": "tri",
         "transform": [{"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 4, 0, 0, 0, 1]}]},
        {"type": "instance", "object": "tri",
         "transform": [{"matrix": [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 4, 0, 0, 0, 1]}]}])"));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], at(4) + ": object \"never\" is never instanced: not translated");
    EXPECT_EQ(importError("ObjectInstance \"ghost\"\n"),
              at(1) + ": ObjectInstance \"ghost\": no such object");
}

TEST_F(PbrtTranslation, GzipCompressedPlyMeshesAreRead) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const auto file = dir_ / "m.ply.gz";
    gzFile out = gzopen(file.string().c_str(), "wb");
    ASSERT_TRUE(out);
    gzwrite(out, ply.data(), unsigned(ply.size()));
    gzclose(out);
    MeshDesc mesh;
    readPly(file, mesh);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.positions[1], Vec3<float>(1, 0, 0));
    const ImportedScene s = import("Shape \"plymesh\" \"string filename\" \"m.ply.gz\"\n");
    EXPECT_EQ(s.scene["shapes"][0]["file"], "m.ply.gz");
    expectLoads();
    // A gzip header followed by garbage.
    const auto broken = write("broken.ply.gz", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00"
                                                           "\x00\x03garbage, not deflate",
                                                           30));
    EXPECT_NE(errorOf([&] { readPly(broken, mesh); }).find("not a valid gzip file"),
              std::string::npos)
        << errorOf([&] { readPly(broken, mesh); });
}

// pbrt-v4 scenes ship compressed geometry files: Include "geometry.pbrt.gz" is read like its
// plain twin; a broken one is refused naming the directive and the file.
TEST_F(PbrtTranslation, GzipCompressedIncludesAreRead) {
    const std::string geometry = "Shape \"sphere\" \"float radius\" 2\n";
    const auto file = dir_ / "geometry.pbrt.gz";
    gzFile out = gzopen(file.string().c_str(), "wb");
    ASSERT_TRUE(out);
    gzwrite(out, geometry.data(), unsigned(geometry.size()));
    gzclose(out);
    const ImportedScene s = import("Include \"geometry.pbrt.gz\"\n");
    ASSERT_EQ(s.scene["shapes"].size(), 1u);
    EXPECT_EQ(s.scene["shapes"][0]["radius"], 2.0);
    write("broken.pbrt.gz", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03garbage", 17));
    EXPECT_NE(importError("Include \"broken.pbrt.gz\"\n").find("not a valid gzip file"),
              std::string::npos);
}

TEST_F(PbrtTranslation, ParserWarningsComeFirstAndInOrder) {
    const ImportedScene s = import(
        "Option \"bool wavefront\" true\nAccelerator \"bvh\"\n"
        "Integrator \"volpath\"\nMaterial \"interface\"\nShape \"sphere\"\n");
    const std::vector<std::string> expected = {
        at(1) + ": Option ignored: pbrt's rendering options do not change lamina's scene",
        at(2) + ": Accelerator ignored: lamina always uses Embree's BVH",
        at(5) +
            ": Shape \"sphere\" with the \"interface\" material separates no media: omitted "
            "(pbrt-v4's rays pass through it)"};
    EXPECT_EQ(s.warnings, expected);
}

}  // namespace
}  // namespace lamina::render
