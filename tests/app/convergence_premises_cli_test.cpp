// `lamina convergence` checks its premises before the first render: a reference of another
// mode, resolution, scene or max_depth is refused in one line without rendering anything; a
// reference too noisy to score the runs is refused (or flagged with --allow-noisy-reference);
// summary.md lists every check. Finished runs are kept in runs/ and --resume continues from
// them: a resumed result equals the uninterrupted one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>

#include "cli_helpers.h"
#include "lamina/image/image_io.h"

namespace lamina {
namespace {

// A glossy sphere under a uniform sky, 16x16: a pass takes milliseconds.
std::string scene(const std::string& roughness = "0.3") {
    return R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
  "film": {"resolution": [16, 16]},
  "materials": {"m": {"type": "standard", "roughness": )" +
           roughness + R"(}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
  "lights": [{"type": "environment", "radiance": 1}]
})";
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ConvergencePremisesCli : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        withoutDrawing();
    }
    // A reference rendered by `lamina render` with another seed than the measured renders.
    std::string reference(const std::string& name, const std::string& options,
                          const std::string& sceneFile) {
        const std::string path = (dir_ / name).string();
        const CommandRun r =
            runLamina("render " + sceneFile + " -q --seed 9 " + options + " -o " + path);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return path;
    }
};

TEST_F(ConvergencePremisesCli, RefusesAReferenceOfAnotherModeResolutionSceneOrDepthAtOnce) {
    const std::string s = write("scene.json", scene());
    const std::string other = write("other.json", scene("0.6"));
    const std::vector<std::pair<std::string, std::string>> cases = {
        {reference("spectral.exr", "--spp 4 --mode spectral", s),
         "the reference was rendered with mode spectral, the measured renders use rgb"},
        {reference("small.exr", "--spp 4 --resolution 8x8", s),
         "the reference is 8x8, the measured renders 16x16"},
        {reference("other.exr", "--spp 4", other),
         "the reference was rendered from other scene files"},
        {reference("shallow.exr", "--spp 4 --max-depth 2", s),
         "the reference was rendered with max_depth 2, the measured renders use 16"},
    };
    for (const auto& [ref, message] : cases) {
        const auto start = std::chrono::steady_clock::now();
        // 30 s per run: a refusal after the first render would take that long.
        const CommandRun r = runLamina("convergence " + s +
                                       " --integrators path --modes rgb --time 30 --reference " +
                                       ref + " -o " + (dir_ / "report").string());
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_EQ(r.output.rfind("lamina: error: " + ref + ": ", 0), 0u) << r.output;
        EXPECT_THAT(r.output, ::testing::HasSubstr(message));
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_LT(seconds, 20) << "refused only after rendering";
        EXPECT_FALSE(fs::exists(dir_ / "report")) << ref;
    }
}

// A 2-sample reference with its variance (render --aovs writes Variance.Y): its noise is far
// above the error a 2-second path-traced run reaches, so it would flatten the slope.
TEST_F(ConvergencePremisesCli, ATooNoisyReferenceIsRefusedUnlessAllowedThenFlagged) {
    const std::string s = write("scene.json", scene());
    const std::string noisy = reference("noisy.exr", "--spp 2 --aovs", s);
    const std::string run =
        "convergence " + s + " --integrators path --modes rgb --time 2 --reference " + noisy;
    const CommandRun refused = runLamina(run + " -o " + (dir_ / "refused").string());
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_THAT(refused.output,
                ::testing::HasSubstr("lamina: error: " + noisy + ": its noise adds "));
    EXPECT_THAT(refused.output, ::testing::HasSubstr("--allow-noisy-reference"));
    EXPECT_FALSE(fs::exists(dir_ / "refused" / "summary.md"));
    // The run it measured is kept for a --resume with the flag.
    EXPECT_TRUE(fs::exists(dir_ / "refused" / "runs" / "path_rgb.csv"));

    const CommandRun allowed = runLamina(run + " --allow-noisy-reference -o " +
                                         (dir_ / "allowed").string() + " 2>/dev/null");
    EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
    const std::string summary = readText(dir_ / "allowed" / "summary.md");
    EXPECT_THAT(summary, ::testing::HasSubstr("## Premises"));
    EXPECT_THAT(summary,
                ::testing::HasSubstr("| rgb | reference noise | flagged | its noise adds"));
    EXPECT_THAT(summary, ::testing::HasSubstr("allowed by --allow-noisy-reference"));
    for (const char* check :
         {"| rgb | mode | holds |", "| rgb | resolution | holds |", "| rgb | scene | holds |",
          "| rgb | max_depth | holds |", "| rgb | independence | holds |"})
        EXPECT_THAT(summary, ::testing::HasSubstr(check));
}

TEST_F(ConvergencePremisesCli, ASelfRenderedReferenceIsFlaggedAndKeepsItsVariance) {
    const std::string s = write("scene.json", scene());
    const CommandRun r = runLamina("convergence " + s +
                                   " --integrators path --modes rgb --time 0.5 --reference-time 2 "
                                   "-o " +
                                   (dir_ / "conv").string() + " 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string summary = readText(dir_ / "conv" / "summary.md");
    EXPECT_THAT(summary, ::testing::HasSubstr("| rgb | reference | flagged | self-rendered"));
    EXPECT_THAT(summary, ::testing::HasSubstr("| rgb | reference noise |"));
    const render::FloatImage ref = render::readFloatImage(dir_ / "conv" / "reference_rgb.exr");
    for (const char* name : {"Variance.R", "Variance.G", "Variance.B"})
        EXPECT_GE(ref.channel(name), 0) << name;
}

// An uninterrupted run, then its directory with one run's file removed (as if interrupted
// after the first run) resumed: the kept run is taken back exactly, the reference is not
// rendered again; resuming a complete directory gives the same convergence.csv byte for byte.
TEST_F(ConvergencePremisesCli, AResumedRunEqualsTheUninterruptedOne) {
    const std::string s = write("scene.json", scene());
    const std::string run = "convergence " + s +
                            " --integrators path,light --modes rgb --time 0.5 "
                            "--reference-time 1 ";
    const fs::path whole = dir_ / "whole", resumed = dir_ / "resumed";
    ASSERT_EQ(runLamina(run + "-o " + whole.string() + " 2>/dev/null").exitCode, 0);
    ASSERT_TRUE(fs::exists(whole / "runs" / "path_rgb.csv"));
    ASSERT_TRUE(fs::exists(whole / "runs" / "light_rgb.csv"));
    fs::create_directories(resumed / "runs");
    fs::copy_file(whole / "reference_rgb.exr", resumed / "reference_rgb.exr");
    fs::copy_file(whole / "runs" / "path_rgb.csv", resumed / "runs" / "path_rgb.csv");
    const CommandRun r = runLaminaStderr(run + "--resume -o " + resumed.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr("path, rgb mode: kept from runs/path_rgb.csv"));
    EXPECT_THAT(r.output, ::testing::Not(::testing::HasSubstr("rendering the rgb reference")));
    // The path rows are the uninterrupted run's; the light run was rendered now.
    const auto rowsOf = [](const fs::path& csv, const std::string& integrator) {
        std::string rows;
        std::istringstream in(readText(csv));
        for (std::string line; std::getline(in, line);)
            if (line.rfind(integrator + ",", 0) == 0) rows += line + "\n";
        return rows;
    };
    EXPECT_EQ(rowsOf(resumed / "convergence.csv", "path"),
              rowsOf(whole / "convergence.csv", "path"));
    EXPECT_FALSE(rowsOf(resumed / "convergence.csv", "light").empty());
    EXPECT_THAT(readText(resumed / "summary.md"),
                ::testing::HasSubstr("Resumed: the runs path rgb"));

    // Everything kept: nothing is rendered, the table is the same byte for byte.
    const std::string uninterrupted = readText(whole / "convergence.csv");
    const CommandRun again = runLaminaStderr(run + "--resume -o " + whole.string());
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_THAT(again.output, ::testing::HasSubstr("light, rgb mode: kept from"));
    EXPECT_EQ(readText(whole / "convergence.csv"), uninterrupted);

    // Another time budget is another measurement: the kept run is refused, named.
    const CommandRun other =
        runLamina("convergence " + s + " --integrators path --modes rgb --time 0.25 --resume -o " +
                  whole.string());
    EXPECT_EQ(other.exitCode, 1) << other.output;
    EXPECT_THAT(other.output, ::testing::HasSubstr((whole / "runs" / "path_rgb.csv").string() +
                                                   ": the run was rendered with time 0.5"));
}

}  // namespace
}  // namespace lamina
