// pbrt-v4 scenes, imported, render the same images as the same scenes written by hand in
// lamina's format (tests/data/interchange/pbrt/: a Cornell box; glass and copper spheres under
// an environment; named metals and a coated diffuse under a blackbody light, with bdpt; an
// instanced mesh, once lamina's reader has instances; clipped quadrics and cylinders, emitting
// ones among them). Each is rendered as 32 independent
// batches from different seeds and compared with the blockwise
// Welch t-test of the estimator-agreement experiment (4x4-pixel blocks, alpha = 0.01): pass
// when at most 3% of the blocks reject, the image means' t-test has p >= 0.0027 and the means
// are within 0.5% of each other. And pbrt's handedness: an emitter on pbrt's image-left comes
// out on the left (and mirrored by Scale -1 1 1, as pbrt does).
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "lamina/experiments/estimator_agreement.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/render/renderer.h"
#include "render_helpers.h"
#include "scratch_directory.h"
#include "source_files.h"

namespace lamina::render {
namespace {

using namespace lamina::experiments;

std::string dataPath(const std::string& name) {
    return (testing::sourceFile("tests/data/interchange/pbrt") / name).string();
}

struct PbrtCase {
    const char* name;
    const char* scene;  ///< NAME.pbrt and NAME.json in tests/data/interchange/pbrt
    int spp;            ///< in all, over the 32 batches
};

class PbrtSceneAgrees : public ::testing::TestWithParam<PbrtCase> {};

TEST_P(PbrtSceneAgrees, ImportedAndHandWrittenScenesRenderTheSameImage) {
    const PbrtCase& c = GetParam();
    SceneDesc imported;
    try {
        imported = loadScene(dataPath(std::string(c.scene) + ".pbrt"));
    } catch (const InputError& e) {
        // The instanced scene translates to lamina's "objects" and "instance" shapes
        // (common-spec.md), which the instances branch adds to the reader; until it is
        // merged, the reader refuses them.
        const std::string what = e.what();
        if (what.find("\"instance\"") == std::string::npos &&
            what.find("objects") == std::string::npos)
            throw;
        GTEST_SKIP() << "lamina's reader has no object instancing yet: " << e.what();
    }
    const SceneDesc handWritten = loadScene(dataPath(std::string(c.scene) + ".json"));
    EXPECT_EQ(imported.format, SceneFormat::Pbrt);
    RenderOptions o;
    o.seed = 1;
    const BatchImages a = renderBatches(imported, o, c.spp, 32);
    o.seed = 7919;
    const BatchImages b = renderBatches(handWritten, o, c.spp, 32);
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 4;
    const AgreementResult r = testAgreement(a, b, test);
    std::printf("  %-14s blocks %.2f%% rejected; mean rel. diff %+.4f +- %.4f (p %.3f)\n", c.name,
                100 * r.blockRejectionRate(), r.relativeDifference, r.standardError, r.meanPValue);
    EXPECT_LE(r.blockRejectionRate(), 0.03);
    EXPECT_GE(r.meanPValue, 0.0027);
    EXPECT_LT(std::abs(r.relativeDifference), 0.005);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PbrtSceneAgrees,
                         ::testing::Values(PbrtCase{"cornell_box", "cornell-box", 2048},
                                           PbrtCase{"glass_sphere", "glass-sphere", 2048},
                                           PbrtCase{"conductor", "conductor", 1024},
                                           PbrtCase{"instanced", "instanced", 1024},
                                           PbrtCase{"quadrics", "quadrics", 2048}),
                         [](const auto& p) { return std::string(p.param.name); });

// The luminance of the image's four quadrants: top-left, top-right, bottom-left,
// bottom-right.
std::array<double, 4> quadrants(const Film& film) {
    std::array<double, 4> q{};
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const int i = (y < film.height() / 2 ? 0 : 2) + (x < film.width() / 2 ? 0 : 1);
            q[std::size_t(i)] += luminance(film.pixel(x, y));
        }
    return q;
}

using PbrtOrientation = lamina::testing::ScratchDirectoryTest;

TEST_F(PbrtOrientation, AnEmitterOnPbrtsUpperLeftComesOutUpperLeft) {
    // pbrt's camera space has +x = cross(up, dir): looking along +z with +y up, x < 0 is on
    // the image's left. A mirroring Scale -1 1 1 before LookAt puts it on the right.
    const std::string body =
        "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 60\n"
        "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 16\n"
        "Sampler \"independent\" \"integer pixelsamples\" 4\nWorldBegin\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Translate -1.2 1.0 4\nShape \"sphere\" \"float radius\" 0.4\nAttributeEnd\n";
    const SceneDesc plain = loadScene(write("plain.pbrt", body));
    const SceneDesc mirrored = loadScene(write("mirrored.pbrt", "Scale -1 1 1\n" + body));
    RenderOptions o;
    const auto q = quadrants(*renderScene(plain, o).film);
    EXPECT_GT(q[0], 0.0);
    EXPECT_EQ(q[1] + q[2] + q[3], 0.0) << q[1] << " " << q[2] << " " << q[3];
    const auto m = quadrants(*renderScene(mirrored, o).film);
    EXPECT_GT(m[1], 0.0);
    EXPECT_EQ(m[0] + m[2] + m[3], 0.0) << m[0] << " " << m[2] << " " << m[3];
}

// An unevenly scaled sphere (placed by an instance: pbrt_shapes.cpp) is the ellipsoid pbrt-v4
// renders: a black one seen by an orthographic camera along its z axis in front of a uniform
// sky of radiance 1 hides pi a b of the screen window's 16 square units (semi-axes a = 1.5,
// b = 0.5). z-test on the film's variance at two-sided significance 0.001, with 2e-3 for the
// pixels' coverage (64 x 64 pixels, 16 samples each). Broken once: the instance placing the
// sphere with the identity (the transform forgotten) hides pi instead: 0.804 against 0.853,
// over 100 standard errors.
TEST_F(PbrtOrientation, AnUnevenlyScaledSphereIsAnEllipsoid) {
    const SceneDesc scene =
        loadScene(write("ellipsoid.pbrt",
                        "LookAt 0 0 -5  0 0 0  0 1 0\n"
                        "Camera \"orthographic\" \"float screenwindow\" [-2 2 -2 2]\n"
                        "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 64\n"
                        "Sampler \"independent\" \"integer pixelsamples\" 16\nWorldBegin\n"
                        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                        "Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
                        "Rotate 30 0 0 1\nScale 1.5 0.5 1\nShape \"sphere\"\n"));
    RenderOptions o;
    o.seed = 3;
    const RenderResult r = renderScene(scene, o);
    const lamina::testing::ImageMean m = lamina::testing::channelMean(*r.film, 1);
    const double expected = 1 - 3.14159265358979 * 1.5 * 0.5 / 16;
    EXPECT_LT(std::abs(m.mean - expected), 3.29 * m.standardError + 2e-3)
        << m.mean << " +- " << m.standardError << ", expected " << expected;
}

// A textured roughness renders as pbrt-v4 remaps it: a conductor sphere under a point light
// whose roughness is a constant texture of 0.09 (alpha sqrt(0.09) = 0.3 after pbrt-v4's
// remapping; lamina's power texture of 1/4 gives roughness 0.09^(1/4), alpha its square) renders
// the image of "float roughness" 0.09, which the importer turns into alpha 0.3 directly.
// The images' means are compared by a z-test at two-sided significance 0.001. Broken once: the
// exponent 1/2 (the remapping left out: alpha 0.09) gives a mean of 0.0571 against 0.0600, fails.
TEST_F(PbrtOrientation, ATexturedRoughnessIsRemappedAsANumberIs) {
    const std::string head =
        "LookAt 0 0 -4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
        "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
        "Sampler \"independent\" \"integer pixelsamples\" 256\nWorldBegin\n"
        "LightSource \"point\" \"rgb I\" [10 10 10] \"point3 from\" [1 1 -3]\n"
        "Texture \"r\" \"float\" \"constant\" \"float value\" 0.09\n";
    const SceneDesc textured = loadScene(
        write("textured.pbrt",
              head + "Material \"conductor\" \"texture roughness\" \"r\"\nShape \"sphere\"\n"));
    const SceneDesc number = loadScene(
        write("number.pbrt",
              head + "Material \"conductor\" \"float roughness\" 0.09\nShape \"sphere\"\n"));
    RenderOptions o;
    o.seed = 11;
    const auto a = lamina::testing::channelMean(*renderScene(textured, o).film, 1);
    o.seed = 12;
    const auto b = lamina::testing::channelMean(*renderScene(number, o).film, 1);
    const double se = std::hypot(a.standardError, b.standardError);
    EXPECT_GT(a.mean, 0.0);
    EXPECT_LT(std::abs(a.mean - b.mean), 3.29 * se)
        << a.mean << " +- " << a.standardError << " against " << b.mean << " +- "
        << b.standardError;
}

using PbrtMedia = lamina::testing::ScratchDirectoryTest;

// pbrt-v4's MakeNamedMedium and MediumInterface, imported: an absorbing medium in an
// interface sphere of radius 1, seen through its diameter by a narrow camera, with an emitter
// of radiance 1 three units behind the sphere, gives exp(-2 sigma_a) per channel (Beer-Lambert;
// the chord of the outermost pixel is 2 (1 - 5e-4), a relative error of at most 5e-4 at
// sigma_a = 1). z-test on the film's per-channel variances, two-sided significance 0.001 per
// channel. Broken once: swapping the inside and outside media (the ink then fills the three
// units between sphere and emitter) fails every channel by 9 to 25 standard errors.
TEST_F(PbrtMedia, AnAbsorbingMediumInAnInterfaceSphereIsBeerLambert) {
    const SceneDesc scene = loadScene(write(
        "ink.pbrt",
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 0.5\n"
        "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "Sampler \"independent\" \"integer pixelsamples\" 64\nWorldBegin\n"
        "MakeNamedMedium \"ink\" \"string type\" \"homogeneous\"\n"
        "  \"rgb sigma_a\" [0.2 0.5 1.0] \"spectrum sigma_s\" [300 0 800 0]\n"
        "AttributeBegin\nMediumInterface \"ink\" \"\"\nMaterial \"interface\"\n"
        "Shape \"sphere\" \"float radius\" 1\nAttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Translate 0 0 4\nRotate 180 1 0 0\nShape \"disk\" \"float radius\" 3\nAttributeEnd\n"));
    ASSERT_EQ(scene.media.size(), 1u);
    RenderOptions o;
    o.seed = 5;
    const RenderResult r = renderScene(scene, o);
    const double sigma[3] = {0.2, 0.5, 1.0};
    for (int c = 0; c < 3; ++c) {
        const lamina::testing::ImageMean m = lamina::testing::channelMean(*r.film, c);
        const double expected = std::exp(-2 * sigma[c]);
        EXPECT_LT(std::abs(m.mean - expected), 3.29 * m.standardError + 5e-4 * expected)
            << "channel " << c << ": " << m.mean << " +- " << m.standardError << ", expected "
            << expected;
    }
}

using PbrtCommandLine = lamina::testing::ScratchDirectoryTest;

TEST_F(PbrtCommandLine, ConvertWritesTheSceneThatRenders) {
    write("m.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float "
          "y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const auto scene = write("s.pbrt",
                             "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\"\n"
                             "Film \"rgb\" \"integer xresolution\" 8 "
                             "\"integer yresolution\" 8\nWorldBegin\n"
                             "AreaLightSource \"diffuse\"\n"
                             "Shape \"plymesh\" \"string filename\" \"m.ply\"\n");
    std::filesystem::create_directories(dir_ / "out");
    const auto out = dir_ / "out" / "s.json";
    const CommandRun run = runLamina("convert " + scene.string() + " -o " + out.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    // The mesh path is relative to the output's directory, and the written scene loads.
    const Json written = readJsonFile(out);
    EXPECT_EQ(written["shapes"][0]["file"], "../m.ply");
    const SceneDesc fromJson = loadScene(out), fromPbrt = loadScene(scene);
    ASSERT_EQ(countShapes<MeshDesc>(fromJson.shapes), 1u);
    EXPECT_EQ(std::get<MeshDesc>(fromJson.shapes[0]).positions,
              std::get<MeshDesc>(fromPbrt.shapes[0]).positions);
    EXPECT_EQ(fromJson.camera.handedness, Handedness::Left);
    EXPECT_EQ(fromJson.film.width, 8);
}

TEST_F(PbrtCommandLine, ErrorsAndWarningsNameFileAndLine) {
    const auto bad = write("bad.pbrt", "WorldBegin\n\nShape \"hyperboloid\"\n");
    const CommandRun run =
        runLaminaStderr("render " + bad.string() + " -o " + (dir_ / "x.exr").string());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.output,
              "lamina: error: " + bad.string() +
                  ":3: Shape \"hyperboloid\" is not supported (lamina reads sphere, "
                  "disk, cylinder, trianglemesh, plymesh, bilinearmesh, loopsubdiv and curve)\n");
    const auto warned = write("warned.pbrt",
                              "Accelerator \"bvh\"\nWorldBegin\n"
                              "LightSource \"point\"\n");
    const CommandRun info = runLaminaStderr("info " + warned.string());
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("lamina: warning: " + warned.string() +
                               ":1: Accelerator ignored: lamina always uses Embree's BVH"),
              std::string::npos)
        << info.output;
}

}  // namespace
}  // namespace lamina::render
