// Every failure is exactly one line on stderr that starts "lamina: error:":
// bad command lines, bad scene and material values whose echoed names hold
// control characters, library errors (yaml-cpp, libpng through OpenImageIO, filesystem
// errors) and usage errors, whose hint is on the same line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_helpers.h"

namespace lamina {
namespace {

struct BadRun {
    const char* name;
    std::string args;  // after `lamina`; SCENE is replaced by a valid scene, DIR by the scratch
    std::string file;  // written to DIR/input.* when not empty
    const char* fileName;
    int exitCode;
    const char* expected;  // a part of the one line
};

class ErrorLines : public CliTest, public ::testing::WithParamInterface<BadRun> {};

std::string substitute(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t i = 0; (i = text.find(from, i)) != std::string::npos; i += to.size())
        text.replace(i, from.size(), to);
    return text;
}

TEST_P(ErrorLines, ExactlyOneLineStartingWithLaminaError) {
    const BadRun& c = GetParam();
    const std::string sceneFile = write("scene.json", kLitSphereScene);
    if (!c.file.empty()) write(c.fileName, c.file);
    const std::string args =
        substitute(substitute(c.args, "SCENE", sceneFile), "DIR", dir_.string());
    const CommandRun r = runLaminaStderr(args);
    EXPECT_EQ(r.exitCode, c.exitCode) << r.output;
    EXPECT_THAT(r.output, ::testing::StartsWith("lamina: error: "));
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr(c.expected)) << r.output;
}

// A scene whose material table holds `material` under the name `name` (JSON text).
std::string sceneWith(const std::string& name, const std::string& material) {
    return substitute(kLitSphereScene, R"("m": {"type": "lambert"})", name + ": " + material);
}

// `depth` mixes inside each other, each over a lambert and the next (docs/bsdf.md, `mix`).
std::string nestedMixes(int depth) {
    std::string json = R"({"type": "lambert"})";
    for (int i = 0; i < depth; ++i)
        json = R"({"type": "mix", "a": {"type": "lambert"}, "b": )" + json + "}";
    return json;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ErrorLines,
    ::testing::Values(
        BadRun{"no_command", "", "", "", 2, "run `lamina --help` for usage"},
        BadRun{"unknown_command", "paint", "", "", 2, "subcommand"},
        BadRun{"unknown_option", "render SCENE --bogus", "", "", 2, "--bogus"},
        BadRun{"missing_scene", "render", "", "", 2, "scene"},
        BadRun{"spp_zero", "render SCENE --spp 0", "", "", 2, "--spp"},
        BadRun{"negative_time", "render SCENE --time -1", "", "", 2,
               "expected a positive number of seconds, got \"-1\""},
        BadRun{"time_not_a_number", "render SCENE --time soon", "", "", 2,
               "positive number of seconds"},
        BadRun{"unknown_mode", "render SCENE --mode infrared", "", "", 2, "infrared"},
        BadRun{"output_not_exr", "render SCENE -o DIR/x.jpg", "", "", 2, "x.jpg"},
        BadRun{"newline_in_key", "render DIR/input.json -o DIR/o.exr -q",
               substitute(kLitSphereScene, R"("film": {)", R"("film": {"res\nolution": 1, )"),
               "input.json", 1, "res\\nolution"},
        BadRun{"escape_in_material_name", "render DIR/input.json -o DIR/o.exr -q",
               sceneWith(R"("m\u001b[31m")", R"({"type": "lambert"})"), "input.json", 1,
               "\\x1b[31m"},
        BadRun{"cylinder_z_min_above_z_max", "render DIR/input.json -o DIR/o.exr -q",
               substitute(kLitSphereScene, R"("type": "sphere", "radius": 1)",
                          R"("type": "cylinder", "z_min": 2, "z_max": -2)"),
               "input.json", 1, "input.json: shapes[0].z_max: expected more than z_min (2)"},
        BadRun{"disk_phi_max_zero", "render DIR/input.json -o DIR/o.exr -q",
               substitute(kLitSphereScene, R"("type": "sphere", "radius": 1)",
                          R"("type": "disk", "phi_max": 0)"),
               "input.json", 1, "input.json: shapes[0].phi_max: "},
        BadRun{"sphere_negative_radius_with_clipping", "info DIR/input.json",
               substitute(kLitSphereScene, R"("type": "sphere", "radius": 1)",
                          R"("type": "sphere", "radius": -1, "z_max": 0.5)"),
               "input.json", 1, "input.json: shapes[0].radius: "},
        BadRun{"blackbody_not_a_temperature", "spectrum blackbody:hot", "", "", 1,
               "blackbody:hot: \"hot\" is not a temperature in kelvin"},
        BadRun{"blackbody_fractional", "spectrum blackbody:6500.5x", "", "", 1,
               "blackbody:6500.5x: \"6500.5x\" is not a temperature"},
        BadRun{"yaml_wrong_node_kind", "spectrum DIR/input.yml",
               "DATA:\n  - type: {tabulated: nk}\n", "input.yml", 1, "input.yml"},
        BadRun{"yaml_malformed", "spectrum DIR/input.yml", "DATA: [\n", "input.yml", 1,
               "input.yml"},
        BadRun{"png_not_a_png", "compare DIR/input.png DIR/input.png", "\x89PNG\r\n\x1a\nnot",
               "input.png", 1, "input.png"},
        BadRun{"material_file_is_a_directory", "bsdf sample @DIR --wo 0,0,1", "", "", 1,
               "lamina: error: "},
        BadRun{"polarisation_neither_scene_nor_material", "polarisation Au Unobtainium -o DIR/p",
               "", "", 1,
               "\"Unobtainium\" is neither a scene file (.json, .pbrt, .xml) nor a "
               "material"},
        BadRun{"polarisation_scene_with_materials", "polarisation SCENE Au -o DIR/p", "", "", 1,
               "a scene goes alone"},
        BadRun{"polarisation_render_option_with_materials", "polarisation Au --spp 4 -o DIR/p", "",
               "", 1, "--spp applies to a scene's renders, not to materials"},
        BadRun{"polarisation_wavelength_out_of_range",
               "polarisation Au --wavelengths 550,1000 -o DIR/p", "", "", 1,
               "--wavelengths: 1000 nm: expected 360 to 830 nm"},
        BadRun{"media_scene_without_media", "media SCENE -o DIR/m", "", "", 1,
               "scene.json: the scene has no participating media"},
        BadRun{"media_reference_with_two_scenes", "media SCENE SCENE --reference SCENE -o DIR/m",
               "", "", 1, ": a reference is one scene's; give one scene with it"},
        BadRun{"render_unknown_ablation", "render SCENE --ablate gravity -o DIR/x.exr", "", "", 2,
               "--ablate"},
        BadRun{"mixes_nested_too_deep", "info DIR/input.json", sceneWith(R"("m")", nestedMixes(17)),
               "input.json", 1,
               "input.json: materials.m: 17 mixes nest inside each other; at most 16 can"}),
    [](const auto& paramInfo) { return std::string(paramInfo.param.name); });

}  // namespace
}  // namespace lamina
