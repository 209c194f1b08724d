// What a new user met in the command's reports: `bench` measuring nothing for a negative count,
// `compare` printing "max 0" for an image of NaNs, `info` counting a rectangle light as two,
// `reciprocity` writing no summary.md and carriage returns into log files, and duplicate keys
// in a scene silently resolved.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cli_helpers.h"
#include "lamina/output/image_output.h"
#include "source_files.h"

namespace lamina {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

const std::string kCornell = testing::sourceFile("scenes/cornell-box.json");

// A count below 1 is a usage error like every other command's (render --spp 0 is one): one
// line naming the option, exit 2, no table of zeros.
TEST_F(CliTest, BenchRefusesNegativeCounts) {
    for (const std::string option : {"--spp -1", "--spp 0", "--threads -3", "--threads 0"}) {
        const CommandRun r = runLamina("bench " + kCornell + " " + option);
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.output;
        EXPECT_THAT(r.output, StartsWith("lamina: error: " + option.substr(0, option.find(' '))))
            << option;
        EXPECT_THAT(r.output, Not(HasSubstr("paths/s"))) << option;
    }
}

// No number printed may be NaN, and a metric over no values is no perfect match: an image of
// NaNs is refused by name; NaNs among finite values are left out, and compare says how many.
TEST_F(CliTest, CompareSaysWhenAnImageHasNoFinitePixels) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto writeExr = [&](const std::string& name, std::vector<float> data) {
        const std::string path = (dir_ / name).string();
        render::writeFloatExr(path, 2, 2, {"R", "G", "B"}, data);
        return path;
    };
    const auto nans = writeExr("nans.exr", std::vector<float>(12, nan));
    const auto grey = writeExr("grey.exr", std::vector<float>(12, 0.5f));
    std::vector<float> some(12, 0.6f);
    some[0] = nan;
    some[4] = std::numeric_limits<float>::infinity();
    const auto partly = writeExr("partly.exr", some);

    const CommandRun all = runLamina("compare " + nans + " " + grey);
    EXPECT_EQ(all.exitCode, 1) << all.output;
    EXPECT_EQ(all.output, "lamina: error: " + nans +
                              ": the image has no finite pixels (every value is NaN or "
                              "infinite): there is nothing to measure\n");
    const CommandRun reference = runLamina("compare " + grey + " " + nans);
    EXPECT_EQ(reference.exitCode, 1);
    EXPECT_THAT(reference.output, StartsWith("lamina: error: " + nans + ": the image has no"));

    const CommandRun part = runLamina("compare " + partly + " " + grey);
    ASSERT_EQ(part.exitCode, 0) << part.output;
    EXPECT_THAT(part.output, Not(HasSubstr("nan")));
    EXPECT_THAT(part.output, HasSubstr("lamina: warning: 2 of 12 channel values are NaN or "
                                       "infinite in one of the images: the metrics are over the "
                                       "other 10"));
    EXPECT_THAT(part.output, HasSubstr("max 0.1"));
}

// The Cornell box's lamp is one rectangle in the file and one light in the renderer.
TEST_F(CliTest, InfoCountsLightsAsTheSceneWritesThem) {
    const CommandRun r = runLamina("info " + kCornell);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_THAT(r.output,
                HasSubstr("lights: 1 emitting shape (sampled as 1 area light), 0 other lights"));
}

// reciprocity ends like every experiment, with summary.md; its progress, written to a file (the
// run's stderr is not a terminal here), has no carriage returns.
TEST_F(CliTest, ReciprocityWritesASummaryAndALogWithoutCarriageReturns) {
    const CommandRun r =
        runLaminaStderr("reciprocity " + kCornell + " --integrators path,light " +
                        "--resolution 16x16 --spp 16 --batches 4 -o " + dir_.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find('\r'), std::string::npos) << r.output;
    EXPECT_THAT(r.output, HasSubstr("path: 4 batches ("));
    EXPECT_THAT(r.output, HasSubstr("light: 4 batches ("));
    std::ifstream in(dir_ / "summary.md");
    const std::string summary((std::istreambuf_iterator<char>(in)), {});
    EXPECT_THAT(summary, HasSubstr("# Reciprocity"));
    EXPECT_THAT(summary, HasSubstr("| path vs light |"));
    EXPECT_THAT(summary, HasSubstr("verdict: the estimators agree"));
}

// A key given twice is refused with its JSON path: the reader would keep one of them silently.
TEST_F(CliTest, ADuplicateKeyInASceneIsRefused) {
    std::ifstream in(kCornell);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string film = "\"film\": {";
    ASSERT_NE(text.find(film), std::string::npos);
    text.insert(text.find(film) + film.size(), "\"resolution\": [4, 4], ");
    const std::string s = write("twice.json", text);
    const CommandRun r = runLamina("info " + s);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.output, "lamina: error: " + s +
                            ": film.resolution: duplicate key: expected each key once in an "
                            "object (JSON keeps only one of them)\n");
}

}  // namespace
}  // namespace lamina
