// Every file a command will write is checked before the work starts:
// an output that is a directory, a preview or error log that cannot be created, a strategies
// directory that is a file, an output that is the input scene under another name, an output
// that is not .exr. Each is refused at once (the render is given 20 seconds: the old code ran
// it and failed at the end), with one line naming the path and nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>

#include "cli_helpers.h"
#include "lamina/output/image_output.h"

namespace lamina {
namespace {

class OutputPaths : public CliTest {
  protected:
    // Runs `render SCENE ARGS --time 20 -q`, expecting a refusal within seconds.
    CommandRun refused(const std::string& args, int exitCode = 1) {
        const auto start = std::chrono::steady_clock::now();
        const CommandRun r = runLaminaStderr("render " + scene_ + " " + args + " --time 20 -q");
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.exitCode, exitCode) << r.output;
        EXPECT_LT(seconds, 10) << "the render ran before the output was checked";
        EXPECT_THAT(r.output, ::testing::StartsWith("lamina: error: "));
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        return r;
    }
    void SetUp() override {
        CliTest::SetUp();
        scene_ = write("scene.json", kLitSphereScene);
    }
    std::string scene_;
};

TEST_F(OutputPaths, AnOutputThatIsADirectoryIsRefused) {
    fs::create_directories(dir_ / "out.exr");
    const CommandRun r = refused("-o " + (dir_ / "out.exr").string());
    EXPECT_THAT(r.output, ::testing::HasSubstr("out.exr: is a directory"));
}

TEST_F(OutputPaths, APreviewThatIsADirectoryIsRefusedBeforeTheExrIsWritten) {
    fs::create_directories(dir_ / "out.png");
    const CommandRun r = refused("-o " + (dir_ / "out.exr").string() + " --preview");
    EXPECT_THAT(r.output, ::testing::HasSubstr("out.png: is a directory"));
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

TEST_F(OutputPaths, AnErrorLogThatCannotBeCreatedIsRefused) {
    // The reference is any image of the right size.
    const CommandRun ok =
        runLamina("render " + scene_ + " -o " + (dir_ / "ref.exr").string() + " --spp 1 -q");
    ASSERT_EQ(ok.exitCode, 0) << ok.output;
    const std::string ref = " --reference " + (dir_ / "ref.exr").string();
    const std::string out = " -o " + (dir_ / "out.exr").string();
    EXPECT_THAT(refused(out + ref + " --error-log " + (dir_ / "none" / "e.csv").string()).output,
                ::testing::HasSubstr("does not exist"));
    // /proc takes no new files, not even from root (whom a mode of 0555 would not stop).
    EXPECT_THAT(refused(out + ref + " --error-log /proc/lamina-e.csv").output,
                ::testing::HasSubstr("cannot create files in the directory /proc"));
    fs::create_directories(dir_ / "e.csv");
    EXPECT_THAT(refused(out + ref + " --error-log " + (dir_ / "e.csv").string()).output,
                ::testing::HasSubstr("is a directory"));
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

TEST_F(OutputPaths, AStrategiesDirectoryThatIsAFileIsRefused) {
    write("strategies", "a file");
    const CommandRun r =
        refused("-o " + (dir_ / "out.exr").string() + " --integrator bdpt --strategies " +
                (dir_ / "strategies").string());
    EXPECT_THAT(r.output, ::testing::HasSubstr("strategies: exists and is not a directory"));
    EXPECT_THAT(refused("-o " + (dir_ / "out.exr").string() +
                        " --integrator bdpt --strategies /proc/lamina-strategies/s")
                    .output,
                ::testing::HasSubstr("cannot create files"));
}

TEST_F(OutputPaths, TheInputSceneIsNeverTheOutput) {
    // The same file by identity: a hard link, and the scene itself named .exr.
    fs::create_hard_link(scene_, dir_ / "link.exr");
    EXPECT_THAT(refused("-o " + (dir_ / "link.exr").string()).output,
                ::testing::HasSubstr("is the input"));
    const auto exrScene = write("scene.exr", kLitSphereScene);
    const CommandRun r = runLaminaStderr("render " + exrScene + " -o " +
                                         (dir_ / "." / "scene.exr").string() + " --spp 1 -q");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr("is the input"));
    std::ifstream in(exrScene);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
              kLitSphereScene);
}

TEST_F(OutputPaths, AnOutputThatIsNotExrIsAUsageError) {
    const CommandRun r = refused("-o " + (dir_ / "x.jpg").string(), 2);
    EXPECT_THAT(r.output, ::testing::HasSubstr("x.jpg: the output is OpenEXR"));
    EXPECT_FALSE(fs::exists(dir_ / "x.jpg"));
}

TEST_F(OutputPaths, ALongOutputNameIsWrittenThroughAShorterTemporaryName) {
    // 254 bytes: the longest name with room for nothing else (the temporary name, ".NAME.tmpPID"
    // in full, would not fit in 255).
    const std::string name = std::string(250, 'n') + ".exr";
    const CommandRun r =
        runLaminaStderr("render " + scene_ + " -o " + (dir_ / name).string() + " --spp 1 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(render::readRgbImage(dir_ / name).width, 8);
    EXPECT_EQ(filesIn(), 2u);  // the scene and the image: no temporary left
    const std::string tooLong = std::string(260, 'n') + ".exr";
    EXPECT_THAT(refused("-o " + (dir_ / tooLong).string()).output,
                ::testing::HasSubstr("file name is longer than"));
}

TEST_F(OutputPaths, AnExperimentsOutputDirectoryIsCheckedBeforeItRuns) {
    write("report", "a file");
    const CommandRun r =
        runLaminaStderr("fresnel Au -o " + (dir_ / "report").string() + " --scene " + scene_);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr("report: exists and is not a directory"));
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
}  // namespace lamina
