// The lamina command and OpenImageIO: the binary does not link it; renders, previews and EXR
// comparisons work with lamina's OpenImageIO module out of reach; a PNG to read or a TIFF to
// write then ends in one error line naming the module, exit 1.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "cli_helpers.h"
#include "source_files.h"

namespace lamina {
namespace {

using ::testing::HasSubstr;

const std::string kCornell = testing::sourceFile("scenes/cornell-box.json");
const std::string kSmall = " --resolution 16x16 --max-depth 3 --spp 1 -q ";
const std::string kNoModule = "/nonexistent/liblamina_oiio_images.so";

TEST(ImageModuleCli, TheBinaryDoesNotLinkOpenImageIo) {
    // What the dynamic loader would load (ldd's own mechanism), without running main.
    const std::string cmd =
        "LD_TRACE_LOADED_OBJECTS=1 " + std::string(LAMINA_BINARY_DIR) + "/app/lamina 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    ASSERT_TRUE(pipe);
    std::string libraries;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), int(buf.size()), pipe))
        libraries += buf.data();
    ::pclose(pipe);
    EXPECT_THAT(libraries, HasSubstr("libc.so"));  // the trace itself worked
    EXPECT_THAT(libraries, ::testing::Not(HasSubstr("OpenImageIO")));
    EXPECT_THAT(libraries, ::testing::Not(HasSubstr("lamina_oiio_images")));
}

/// LAMINA_OIIO_MODULE set for the runs of one test (the child processes inherit it).
class NoModule : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        ::setenv("LAMINA_OIIO_MODULE", kNoModule.c_str(), 1);
    }
    void TearDown() override {
        ::unsetenv("LAMINA_OIIO_MODULE");
        CliTest::TearDown();
    }
};

TEST_F(NoModule, ExrAndPngNeedNoModuleOtherFormatsNameIt) {
    const std::string exr = (dir_ / "out.exr").string(), png = (dir_ / "out.png").string();
    const CommandRun render = runLamina("render " + kCornell + kSmall + "-o " + exr + " --preview");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    ASSERT_TRUE(fs::exists(png));
    const CommandRun same = runLamina("compare " + exr + " " + exr);
    EXPECT_EQ(same.exitCode, 0) << same.output;

    const CommandRun read = runLamina("compare " + png + " " + png);
    EXPECT_EQ(read.exitCode, 1);
    EXPECT_EQ(read.output, "lamina: error: " + png +
                               ": reading .png images needs lamina's OpenImageIO module (" +
                               kNoModule + "): " + kNoModule +
                               ": cannot open shared object file: No such file or directory\n");
    // The difference image of `compare --diff` in a format only OpenImageIO writes.
    const std::string tif = (dir_ / "diff.tif").string();
    const CommandRun write = runLaminaStderr("compare " + exr + " " + exr + " --diff " + tif);
    EXPECT_EQ(write.exitCode, 1);
    EXPECT_EQ(write.output, "lamina: error: " + tif +
                                ": writing .tif images needs lamina's OpenImageIO module (" +
                                kNoModule + "): " + kNoModule +
                                ": cannot open shared object file: No such file or directory\n");
    EXPECT_FALSE(fs::exists(tif));

    // With the module in reach (the build's), the same PNG reads and the TIFF is written.
    ::unsetenv("LAMINA_OIIO_MODULE");
    const CommandRun again = runLamina("compare " + png + " " + png);
    EXPECT_EQ(again.exitCode, 0) << again.output;
    const CommandRun tiff = runLamina("compare " + exr + " " + exr + " --diff " + tif);
    EXPECT_EQ(tiff.exitCode, 0) << tiff.output;
    EXPECT_TRUE(fs::exists(tif));
}

}  // namespace
}  // namespace lamina
