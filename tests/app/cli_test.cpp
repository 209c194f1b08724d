// The `lamina` command line as a user meets it: exit codes, one clear error line naming the
// file and JSON path, and nothing written when the input is bad.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include <fstream>

#include "cli_helpers.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/json_reader.h"
#include "lamina/output/image_output.h"
#include "lamina/render/render_memory.h"
#include "source_files.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

// A valid small scene whose parts the bad-input cases replace.
std::string scene(const std::string& material, const std::string& emission = "[1, 1, 1]",
                  const std::string& extraShape = "") {
    return R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
  "film": {"resolution": [8, 8]},
  "materials": {"m": )" +
           material + R"(},
  "shapes": [)" +
           extraShape + R"(
    {"type": "sphere", "radius": 1, "material": "m"},
    {"type": "rectangle", "material": "m", "transform": [{"translate": [0, 3, 0]}],
     "emission": {"radiance": )" +
           emission + R"(}}
  ]
})";
}

TEST_F(CliTest, RendersAValidSceneWithMetadata) {
    const auto s = write("ok.json", scene(R"({"type": "lambert"})"));
    const auto out = (dir_ / "ok.exr").string();
    const CommandRun r = runLamina("render " + s + " -o " + out + " --spp 2 --seed 7 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto img = render::readRgbImage(out);
    EXPECT_EQ(img.width, 8);
    EXPECT_EQ(img.metadata.at("lamina:mode"), "rgb");
    EXPECT_EQ(img.metadata.at("lamina:spp"), "2");
    EXPECT_EQ(img.metadata.at("lamina:seed"), "7");
    EXPECT_EQ(img.metadata.at("lamina:partial"), "0");
    EXPECT_EQ(filesIn(), 2u);  // the scene and the image, no temporary left behind
}

TEST_F(CliTest, AovLayersHaveTheirNamesAndMeanings) {
    // A Lambert sphere of albedo 0.3 seen head-on: the Albedo layer holds 0.3, N.Z points at
    // the camera (-1 along z towards it), Z is the distance to the sphere.
    const auto s = write("aov.json", R"({
      "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 5},
      "film": {"resolution": [4, 4]},
      "materials": {"m": {"type": "lambert", "reflectance": 0.3}},
      "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
      "lights": [{"type": "environment", "radiance": 1}]
    })");
    const auto out = (dir_ / "aov.exr").string();
    ASSERT_EQ(runLamina("render " + s + " -o " + out + " --spp 4 --aovs -q").exitCode, 0);
    const render::FloatImage image = render::readFloatImage(out);
    const std::vector<std::string> expected = {
        "R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z", "Z", "Variance.Y"};
    ASSERT_EQ(image.channels.size(), expected.size());
    // EXR stores channels sorted by name: look them up by name.
    std::map<std::string, float> centre;
    for (std::size_t c = 0; c < expected.size(); ++c)
        centre[image.channels[c]] = image.at(2, 2, int(c));
    for (const auto& name : expected)
        EXPECT_EQ(centre.count(name), 1u) << name;
    EXPECT_NEAR(centre["Albedo.G"], 0.3f, 1e-4f);
    EXPECT_NEAR(centre["N.Z"], -1.0f, 1e-2f);
    EXPECT_NEAR(centre["Z"], 4.0f, 1e-2f);
    EXPECT_GE(centre["Variance.Y"], 0.0f);
}

TEST_F(CliTest, CompareReportsKnownDifferences) {
    // A = B + 0.1 everywhere, B = 0.5: mse 0.01, rmse 0.1, mae 0.1, max 0.1,
    // relmse 0.01 / (0.25 + 0.01).
    auto writeExr = [&](const std::string& name, int w, int h, float v) {
        const std::string path = (dir_ / name).string();
        std::vector<float> data(std::size_t(w) * h * 3, v);
        render::writeFloatExr(path, w, h, {"R", "G", "B"}, data);
        return path;
    };
    const auto a = writeExr("a.exr", 4, 4, 0.6f), b = writeExr("b.exr", 4, 4, 0.5f);
    const auto diff = (dir_ / "diff.png").string();
    const CommandRun r = runLamina("compare " + a + " " + b + " --diff " + diff);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::map<std::string, double> m;
    std::istringstream lines(r.output);
    for (std::string name; lines >> name;)
        lines >> m[name];
    EXPECT_NEAR(m["mse"], 0.01, 1e-6);
    EXPECT_NEAR(m["rmse"], 0.1, 1e-6);
    EXPECT_NEAR(m["mae"], 0.1, 1e-6);
    EXPECT_NEAR(m["max"], 0.1, 1e-6);
    EXPECT_NEAR(m["relmse"], 0.01 / 0.26, 1e-6);
    EXPECT_TRUE(fs::exists(diff));
    // The scale of the false colours is printed; the figure (PDF beside the PNG) is drawn from
    // its data, also beside it.
    EXPECT_NEAR(m["diff_scale"], 0.1, 1e-6);
    for (const char* f : {"diff.pdf", "diff.figure.json", "diff.f32"})
        EXPECT_TRUE(fs::exists(dir_ / f)) << f;
    // One bright pixel (a lamp's edge) in 256 does not set the scale: the 99th percentile does.
    {
        std::vector<float> lit(16 * 16 * 3, 0.51f), dark(16 * 16 * 3, 0.5f);
        lit[0] = lit[1] = lit[2] = 10.5f;
        const std::string c = (dir_ / "c.exr").string(), d = (dir_ / "d.exr").string();
        render::writeFloatExr(c, 16, 16, {"R", "G", "B"}, lit);
        render::writeFloatExr(d, 16, 16, {"R", "G", "B"}, dark);
        const CommandRun edge = runLamina("compare " + c + " " + d + " --metric max --diff " +
                                          (dir_ / "edge.png").string());
        ASSERT_EQ(edge.exitCode, 0) << edge.output;
        std::map<std::string, double> e;
        std::istringstream out(edge.output);
        for (std::string name; out >> name;)
            out >> e[name];
        EXPECT_NEAR(e["max"], 10, 1e-5);
        EXPECT_NEAR(e["diff_scale"], 0.01, 1e-6);
    }
    const auto small = writeExr("small.exr", 2, 4, 0.5f);
    const CommandRun mismatch = runLamina("compare " + a + " " + small);
    EXPECT_EQ(mismatch.exitCode, 1);
    EXPECT_THAT(mismatch.output, ::testing::HasSubstr("is 4x4 but"));
    EXPECT_EQ(runLamina("compare " + a + " " + b + " --metric psnr").exitCode, 2);
}

struct BadInput {
    const char* name;
    std::string sceneText;
    const char* expected;
};

class CliBadInput : public CliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliBadInput, ExitsWithOneClearErrorAndWritesNothing) {
    const auto s = write("scene.json", GetParam().sceneText);
    const auto out = (dir_ / "out.exr").string();
    const CommandRun r = runLamina("render " + s + " -o " + out + " -q");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr("scene.json"));
    EXPECT_THAT(r.output, ::testing::HasSubstr(GetParam().expected));
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(filesIn(), 1u);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"malformed_json", "{\n  \"camera\": {\n    \"fov\": 40,,\n  }\n}",
                 "malformed JSON at line 3"},
        BadInput{"unknown_key", scene(R"({"type": "lambert", "reflectanse": 0.5})"),
                 "materials.m.reflectanse: unknown key"},
        BadInput{"wrong_type", scene(R"({"type": "lambert", "reflectance": "red"})"),
                 "materials.m.reflectance: expected a number"},
        BadInput{"negative_radiance", scene(R"({"type": "lambert"})", "[1, -1, 1]"),
                 "shapes[1].emission.radiance[1]: expected a number >= 0, got -1"},
        BadInput{"roughness_out_of_range", scene(R"({"type": "standard", "roughness": 1.5})"),
                 "materials.m.roughness: expected a number in [0, 1], got 1.5"},
        BadInput{"unknown_material_type", scene(R"({"type": "velvet"})"),
                 "unknown material type \"velvet\""},
        BadInput{"zero_area_light",
                 scene(R"({"type": "lambert"})", "1",
                       R"({"type": "mesh", "material": "m", "positions": [[0,0,0],[1,0,0],[2,0,0]],
                           "faces": [[0,1,2]], "emission": {"radiance": 1}},)"),
                 "shapes[0].emission: the emitting shape has zero area"},
        BadInput{"missing_mesh",
                 scene(R"({"type": "lambert"})", "1",
                       R"({"type": "obj", "file": "nowhere.obj", "material": "m"},)"),
                 "nowhere.obj: no such file"},
        BadInput{"unknown_material_name",
                 scene(R"({"type": "lambert"})", "1", R"({"type": "sphere", "material": "gold"},)"),
                 "shapes[0].material: unknown material \"gold\""},
        BadInput{"no_light", R"({"shapes": []})", "the scene has no light"}),
    [](const auto& paramInfo) { return std::string(paramInfo.param.name); });

TEST_F(CliTest, UnwritableOutputIsReportedBeforeRendering) {
    const auto s = write("ok.json", scene(R"({"type": "lambert"})"));
    const CommandRun r = runLamina("render " + s + " -o " + (dir_ / "missing" / "x.exr").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.output, ::testing::HasSubstr("does not exist"));
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
    const auto s = write("ok.json", scene(R"({"type": "lambert"})"));
    EXPECT_EQ(runLamina("render " + s + " --spp 0").exitCode, 2);
    EXPECT_EQ(runLamina("render " + s + " --mode infrared").exitCode, 2);
    EXPECT_EQ(runLamina("render").exitCode, 2);
    EXPECT_EQ(runLamina("render --help").exitCode, 0);
}

// strtod accepts "nan", "inf" and overflowing literals; every floating option refuses them
// (--time's own check, a positive number of seconds, sees them first and refuses them in its
// words).
TEST_F(CliTest, FloatingOptionsRefuseNanAndInfinity) {
    const auto s = write("ok.json", scene(R"({"type": "lambert"})"));
    const auto out = (dir_ / "never.exr").string();
    for (const std::string option : {"--time nan", "--time inf", "--time 1e999", "--exposure nan",
                                     "--exposure -inf", "--exposure NAN", "--exposure 1e999"}) {
        const CommandRun r = runLamina("render " + s + " -o " + out + " -q " + option);
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.output;
        EXPECT_THAT(r.output, ::testing::StartsWith("lamina: error: " + option.substr(0, 6)))
            << option;
        EXPECT_THAT(r.output, ::testing::HasSubstr(option.starts_with("--time")
                                                       ? "expected a positive number of seconds"
                                                       : "expected a finite number"))
            << option;
        EXPECT_FALSE(fs::exists(out)) << option;
    }
    // Other commands' floating options have the same check.
    EXPECT_EQ(runLamina("reciprocity " + s + " --alpha nan").exitCode, 2);
    // Finite values still pass the check.
    EXPECT_EQ(runLamina("render " + s + " -o " + out + " -q --spp 1 --exposure -1.5").exitCode, 0);
}

// The memory of the film is estimated before anything is allocated: printed by `info`,
// refused when it exceeds what the machine has (it used to end in std::bad_alloc); the
// command line's resolution has the scene key's bound.
TEST_F(CliTest, RenderMemoryIsPrintedAndCheckedUpFront) {
    std::string text = scene(R"({"type": "lambert"})");
    text.replace(text.find("[8, 8]"), 6, "[1024, 1024]");
    const auto s = write("big.json", text);
    const CommandRun info = runLamina("info " + s);
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_THAT(
        info.output,
        ::testing::HasSubstr(
            "render memory: ~" +
            render::formatBytes(render::estimateRenderMemory(1024, 1024, false, false).total())));
    const auto out = (dir_ / "huge.exr").string();
    const CommandRun huge =
        runLamina("render " + s + " -o " + out + " -q --resolution 65536x65536");
    EXPECT_EQ(huge.exitCode, 1) << huge.output;
    EXPECT_THAT(huge.output,
                ::testing::StartsWith("lamina: error: --resolution: 65536x65536 needs ~"));
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(runLamina("render " + s + " -o " + out + " -q --resolution 65537x16").exitCode, 2);
}

// `info` counts the instances and the triangles they reference against those stored: the tree
// of the scene has 12 triangles (a trunk of 4 quads, two cards), placed 16 times.
TEST_F(CliTest, InfoCountsInstancesAndTheTrianglesTheyReference) {
    const CommandRun info =
        runLamina("info " + testing::sourceFile("scenes/instances-and-cutouts.json").string());
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_THAT(info.output,
                ::testing::HasSubstr("instances: 16 of 1 objects, referencing 192 triangles (12 "
                                     "stored once in the objects)"));
}

TEST_F(CliTest, BsdfEvalMatchesTheLibraryAndSampleCountsLines) {
    const std::string material =
        R"('{"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.4}')";
    const CommandRun e =
        runLamina("bsdf eval " + material, R"({"wo":[0.3,0,1],"wi":[-0.2,0.1,1]})");
    ASSERT_EQ(e.exitCode, 0) << e.output;
    const Json j = Json::parse(e.output);
    const auto desc =
        parseMaterialArgument(R"({"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.4})");
    const auto bsdf = buildBxdf(desc, SpectrumContext<Rgb<double>>{});
    const Vec3<double> wo = glm::normalize(Vec3<double>(0.3, 0, 1)),
                       wi = glm::normalize(Vec3<double>(-0.2, 0.1, 1));
    const auto f = bsdf->eval(wo, wi, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(j["f"][std::size_t(c)].get<double>(), f[c], 1e-8 * f[c]);
    EXPECT_NEAR(j["pdf"].get<double>(), bsdf->pdf(wo, wi), 1e-8);
    EXPECT_NEAR(j["pdf_reverse"].get<double>(), bsdf->pdf(wi, wo), 1e-8);

    const CommandRun s = runLamina("bsdf sample " + material + " --wo 0,0.2,1 --count 25");
    ASSERT_EQ(s.exitCode, 0) << s.output;
    EXPECT_EQ(std::count(s.output.begin(), s.output.end(), '\n'), 25);
    const CommandRun c = runLamina("bsdf chi2 " + material + " --wo 0.5,0,0.5 --samples 100000");
    EXPECT_THAT(c.output, ::testing::HasSubstr("accepted"));
}

TEST_F(CliTest, BsdfBadInputIsReported) {
    const CommandRun e = runLamina(R"(bsdf eval '{"type":"lambert"}')", R"({"wo":[0,0,1]})");
    EXPECT_EQ(e.exitCode, 1);
    EXPECT_THAT(e.output, ::testing::HasSubstr("<stdin> line 1: wi: missing"));
    const CommandRun m = runLamina(R"(bsdf sample '{"type":"lambert","roughness":-1}' --wo 0,0,1)");
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_THAT(m.output, ::testing::HasSubstr("roughness"));
    EXPECT_EQ(runLamina(R"(bsdf sample '{"type":"lambert"}' --wo 0,0,0)").exitCode, 2);
}

}  // namespace
}  // namespace lamina
