// Which importer reads a scene file (scene_import.h): by extension, else by the first
// character; and the paths importers write into the translated document.
#include <gtest/gtest.h>

#include "lamina/interchange/scene_import.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using SceneImport = lamina::testing::ScratchDirectoryTest;

TEST_F(SceneImport, FormatByExtension) {
    // The extension decides even against the content: a .pbrt file that starts with '{' is
    // still read as pbrt-v4 (and fails there, naming its line).
    EXPECT_EQ(detectSceneFormat(write("a.json", "Camera \"perspective\"")), SceneFormat::Lamina);
    EXPECT_EQ(detectSceneFormat(write("a.pbrt", "{}")), SceneFormat::Pbrt);
    EXPECT_EQ(detectSceneFormat(write("a.xml", "{}")), SceneFormat::Mitsuba);
}

TEST_F(SceneImport, FormatByFirstCharacter) {
    EXPECT_EQ(detectSceneFormat(write("a", "\n  {\"shapes\": []}")), SceneFormat::Lamina);
    EXPECT_EQ(detectSceneFormat(write("b", " <?xml version=\"1.0\"?><scene/>")),
              SceneFormat::Mitsuba);
    EXPECT_EQ(detectSceneFormat(write("c", "# a comment\nLookAt 0 0 0 0 0 1 0 1 0")),
              SceneFormat::Pbrt);
    EXPECT_EQ(detectSceneFormat(write("d", "")), SceneFormat::Pbrt);
}

TEST_F(SceneImport, MissingFileIsNamed) {
    EXPECT_EQ(lamina::testing::errorOf([&] { detectSceneFormat(dir_ / "absent"); }),
              (dir_ / "absent").string() + ": cannot open the scene file");
}

TEST_F(SceneImport, LaminaSceneIsNotConverted) {
    const auto file = write("s.json", "{}");
    EXPECT_EQ(lamina::testing::errorOf([&] { importScene(file, dir_); }),
              file.string() + ": is a lamina scene already; nothing to convert");
}

TEST_F(SceneImport, DocumentPathsAreRelativeWhereReachable) {
    EXPECT_EQ(documentPath(dir_ / "meshes" / "a.ply", dir_), "meshes/a.ply");
    EXPECT_EQ(documentPath(dir_ / "a.ply", dir_ / "out"), "../a.ply");
    EXPECT_EQ(documentPath(dir_ / "x" / ".." / "a.ply", dir_), "a.ply");
}

}  // namespace
}  // namespace lamina::render
