// `lamina convert --check DIR` (scene_corpus.h): every scene file under a directory, loaded as
// `lamina render` loads it: a good file loads (with its warning count), a refused one and a
// broken one are listed with the first line of their error, naming file and line; other files
// are not scenes and are skipped.
#include <gtest/gtest.h>

#include "cli_helpers.h"
#include "lamina/scene/scene_corpus.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

class ConvertCheck : public lamina::testing::ScratchDirectoryTest {
  protected:
    void SetUp() override {
        ScratchDirectoryTest::SetUp();
        // Loads, with one warning (the filename ignored).
        write("good.pbrt",
              "Film \"rgb\" \"string filename\" \"x.exr\"\nCamera \"perspective\"\nWorldBegin\n"
              "LightSource \"point\" \"rgb I\" [1 1 1]\n");
        // Refused: a camera lamina does not have, on line 2.
        write("refused.pbrt", "Film \"rgb\"\nCamera \"spherical\"\nWorldBegin\n");
        // Broken: not XML past its first element (line 2).
        std::filesystem::create_directories(dir_ / "sub");
        write("sub/broken.xml", "<scene version=\"3.0.0\">\n<shape type=\"sphere\"\n");
        write("notes.txt", "not a scene");
    }
};

TEST_F(ConvertCheck, ListsWhatLoadsAndWhyTheRestIsRefused) {
    const auto entries = checkSceneCorpus(dir_);
    ASSERT_EQ(entries.size(), 3u);
    EXPECT_EQ(entries[0].file, dir_ / "good.pbrt");
    EXPECT_TRUE(entries[0].loads);
    EXPECT_EQ(entries[0].warnings, 1u);
    EXPECT_EQ(entries[1].file, dir_ / "refused.pbrt");
    EXPECT_FALSE(entries[1].loads);
    EXPECT_EQ(
        entries[1].error.rfind((dir_ / "refused.pbrt").string() + ":2: Camera \"spherical\"", 0),
        0u)
        << entries[1].error;
    EXPECT_EQ(entries[2].file, dir_ / "sub" / "broken.xml");
    EXPECT_FALSE(entries[2].loads);
    EXPECT_EQ(entries[2].format, SceneFormat::Mitsuba);
    EXPECT_EQ(entries[2].error.rfind((dir_ / "sub" / "broken.xml").string() + ":", 0), 0u)
        << entries[2].error;
    EXPECT_EQ(entries[2].error.find('\n'), std::string::npos);
}

TEST_F(ConvertCheck, TheCommandPrintsTheTableAndTheCount) {
    const CommandRun run = runLamina("convert --check " + dir_.string(), "", " 2>/dev/null");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    // Columns: status, format, warnings, then the file or its error line.
    EXPECT_NE(
        run.output.find("loads    pbrt-v4         1  " + (dir_ / "good.pbrt").string() + "\n"),
        std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("refused  pbrt-v4         -  " + (dir_ / "refused.pbrt").string() +
                              ":2: Camera \"spherical\" is not supported"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("refused  mitsuba         -  " +
                              (dir_ / "sub" / "broken.xml").string() + ":2: "),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("3 scene files: 1 load, 2 refused"), std::string::npos) << run.output;
    // Nothing is printed on stderr: the warnings are counted, not repeated.
    EXPECT_EQ(runLaminaStderr("convert --check " + dir_.string()).output, "");
    const CommandRun both =
        runLamina("convert " + (dir_ / "good.pbrt").string() + " --check " + dir_.string());
    EXPECT_EQ(both.exitCode, 2) << both.output;
}

}  // namespace
}  // namespace lamina::render
