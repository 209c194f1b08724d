// Numbers a user can trust: a render's EXR names everything that made it (every
// input file in the scene hash, every effective setting); `convergence` refuses a reference
// correlated with its measured renders; `compare` matches channels by name and refuses a
// display image against a linear one; `bsdf plot` draws the plane that contains wo.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "cli_helpers.h"
#include "lamina/output/image_output.h"

namespace lamina {
namespace {

// A white furnace (exact image: 1 everywhere) with its sphere replaced by an OBJ file.
const char* kMeshScene = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30},
  "film": {"resolution": [16, 16]},
  "materials": {"white": {"type": "lambert", "reflectance": 0.5}},
  "shapes": [{"type": "obj", "file": "quad.obj", "material": "white"}],
  "lights": [{"type": "environment", "radiance": 1}]
})";

const char* kQuad = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";

const char* kFurnace = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30},
  "film": {"resolution": [16, 16]},
  "integrator": {"max_depth": 64, "rr_depth": 64},
  "materials": {"white": {"type": "lambert", "reflectance": 1}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "white"}],
  "lights": [{"type": "environment", "radiance": 1}]
})";

class ProvenanceCli : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        withoutDrawing();
    }
    render::RgbImage render(const std::string& scene, const std::string& name,
                            const std::string& options = "--spp 2") {
        const std::string out = (dir_ / name).string();
        const CommandRun r = runLamina("render " + scene + " -q " + options + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return render::readRgbImage(out);
    }
};

TEST_F(ProvenanceCli, TheSceneHashCoversTheMeshFileAndEverySettingIsRecorded) {
    const std::string scene = write("mesh.json", kMeshScene);
    write("quad.obj", kQuad);
    const render::RgbImage before = render(scene, "a.exr", "--time 0.5");
    for (const char* key : {"version",
                            "git_commit",
                            "command_line",
                            "mode",
                            "integrator",
                            "scene",
                            "scene_hash",
                            "input_files",
                            "sampler",
                            "mis_heuristic",
                            "light_selection",
                            "filter",
                            "filter_radius",
                            "spp",
                            "seed",
                            "max_depth",
                            "rr_depth",
                            "partial",
                            "rejected_samples",
                            "seconds",
                            "time_budget",
                            "camera_to_world",
                            "world_to_ndc"})
        EXPECT_TRUE(before.metadata.count(std::string("lamina:") + key)) << key;
    EXPECT_EQ(before.metadata.at("lamina:input_files"), "2");  // the JSON and the OBJ
    EXPECT_EQ(before.metadata.at("lamina:filter"), "box");
    EXPECT_EQ(before.metadata.at("lamina:time_budget"), "0.5");
    EXPECT_THAT(before.metadata.at("lamina:command_line"), ::testing::HasSubstr("--time 0.5"));
    EXPECT_FALSE(before.metadata.at("lamina:git_commit").empty());

    // The same JSON, another mesh: another hash.
    write("quad.obj", std::string(kQuad) + "v 0 0 0\n");
    const render::RgbImage after = render(scene, "b.exr");
    EXPECT_NE(before.metadata.at("lamina:scene_hash"), after.metadata.at("lamina:scene_hash"));
    EXPECT_EQ(after.metadata.at("lamina:time_budget"), "0");
}

TEST_F(ProvenanceCli, ConvergenceRefusesAReferenceWithTheMeasuredSamplerAndSeed) {
    const std::string scene = write("furnace.json", kFurnace);
    // The scene's seed (0) and sampler (Sobol): the measured renders' own samples.
    render(scene, "correlated.exr");
    const std::string correlated = (dir_ / "correlated.exr").string();
    const std::string run =
        "convergence " + scene + " --integrators path --time 0.3 --reference " + correlated;
    const CommandRun refused = runLamina(run + " -o " + (dir_ / "c1").string());
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_THAT(refused.output, ::testing::HasSubstr("correlated"));
    EXPECT_THAT(refused.output, ::testing::HasSubstr("--allow-correlated-reference"));
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << refused.output;

    const CommandRun allowed =
        runLamina(run + " --allow-correlated-reference -o " + (dir_ / "c2").string());
    EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
    EXPECT_THAT(allowed.output, ::testing::HasSubstr("understated"));

    // Another seed is independent; an image without lamina metadata is accepted with a note.
    render(scene, "independent.exr", "--spp 2 --seed 9");
    EXPECT_EQ(runLamina("convergence " + scene + " --integrators path --time 0.3 --reference " +
                        (dir_ / "independent.exr").string() + " -o " + (dir_ / "c3").string())
                  .exitCode,
              0);
    const std::string foreign = (dir_ / "foreign.exr").string();
    render::writeFloatExr(foreign, 16, 16, {"R", "G", "B"}, std::vector<float>(16 * 16 * 3, 1.0f));
    const CommandRun other =
        runLamina("convergence " + scene + " --integrators path --time 0.3 --reference " + foreign +
                  " -o " + (dir_ / "c4").string());
    EXPECT_EQ(other.exitCode, 0) << other.output;
    EXPECT_THAT(other.output, ::testing::HasSubstr("without lamina metadata"));
}

TEST_F(ProvenanceCli, CompareMatchesChannelsByNameAndRefusesADisplayImage) {
    const int n = 4 * 4;
    // R = 0.25, G = 0.5, B = 0.75, preceded (in name order) by layers of other values.
    std::vector<float> layered, plain;
    for (int i = 0; i < n; ++i) {
        layered.insert(layered.end(), {9.0f, 9.0f, 9.0f, 0.75f, 0.5f, 0.25f});
        plain.insert(plain.end(), {0.25f, 0.5f, 0.75f});
    }
    const std::string a = (dir_ / "layered.exr").string(), b = (dir_ / "plain.exr").string();
    render::writeFloatExr(a, 4, 4, {"Albedo.B", "Albedo.G", "Albedo.R", "B", "G", "R"}, layered);
    render::writeFloatExr(b, 4, 4, {"R", "G", "B"}, plain);
    const CommandRun same = runLamina("compare " + a + " " + b + " --metric mse");
    ASSERT_EQ(same.exitCode, 0) << same.output;
    EXPECT_EQ(same.output, "mse 0\n");

    // Three channels that are not R, G, B (an AOV file): refused, naming what was found,
    // instead of compared by position.
    const std::string normals = (dir_ / "normals.exr").string();
    render::writeFloatExr(normals, 4, 4, {"N.X", "N.Y", "N.Z"}, plain);
    const CommandRun aov = runLamina("compare " + normals + " " + b);
    EXPECT_EQ(aov.exitCode, 1) << aov.output;
    EXPECT_THAT(aov.output, ::testing::HasSubstr("expected channels R, G and B, found N.X"));

    const std::string png = (dir_ / "display.png").string();
    render::writeRgb8(png, 4, 4, plain);
    const CommandRun mixed = runLamina("compare " + png + " " + b);
    EXPECT_EQ(mixed.exitCode, 1) << mixed.output;
    EXPECT_THAT(mixed.output, ::testing::HasSubstr("sRGB"));
    // A display image is decoded to linear: 0.5 in sRGB is 0.214 linear.
    const render::RgbImage decoded = render::readRgbImage(png);
    EXPECT_TRUE(decoded.displayReferred);
    EXPECT_NEAR(decoded.at(0, 0, 1), 0.2140, 0.003);
}

double plotPeak(const std::string& output) {
    const std::regex peak(R"(0\); peak ([0-9.eE+-]+))");
    std::smatch m;
    if (!std::regex_search(output, m, peak)) return -1;
    return std::stod(m[1]);
}

TEST_F(ProvenanceCli, BsdfPlotDrawsThePlaneThatContainsWo) {
    // An isotropic glossy lobe: its plane of incidence looks the same for any azimuth of wo,
    // and it peaks near the mirror direction, which lies in that plane.
    const std::string material = R"('{"type":"conductor","material":"Au","alpha":0.1}')";
    const std::string png = (dir_ / "plot.png").string();
    const CommandRun x = runLamina("bsdf plot " + material + " --wo 0.6,0,0.8 -o " + png);
    const CommandRun y = runLamina("bsdf plot " + material + " --wo 0,0.6,0.8 -o " + png);
    ASSERT_EQ(x.exitCode, 0) << x.output;
    ASSERT_EQ(y.exitCode, 0) << y.output;
    const double px = plotPeak(x.output), py = plotPeak(y.output);
    ASSERT_GT(px, 0) << x.output;
    EXPECT_NEAR(py, px, 1e-3 * px) << y.output;
}

}  // namespace
}  // namespace lamina
