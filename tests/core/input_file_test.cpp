// The gate every reader goes through (input_file.h) and the JSON reader's bounds: a path
// that is a directory, a FIFO or a device is refused before it is opened (readers hung on
// them), a file larger than its kind's limit is refused, JSON nesting is bounded (100 000
// levels crashed) and no message echoes a whole value.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/core/json_reader.h"

#include "scratch_directory.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;
using testing::errorOf;
using ::testing::HasSubstr;

class InputFiles : public testing::ScratchDirectoryTest {};

TEST_F(InputFiles, ADirectoryAFifoAndADeviceAreRefusedBeforeOpening) {
    EXPECT_THAT(errorOf([&] { readInputFile(dir_, kMaxTextFileBytes); }),
                HasSubstr(dir_.string() + ": is a directory, not a regular file"));
    const fs::path fifo = dir_ / "fifo.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Opening a FIFO blocks until a writer comes: the check must not open it.
    EXPECT_THAT(errorOf([&] { readJsonFile(fifo); }), HasSubstr("fifo.json: is a FIFO"));
    EXPECT_THAT(errorOf([&] { readJsonFile("/dev/zero"); }),
                HasSubstr("/dev/zero: is a device, not a regular file"));
    EXPECT_THAT(errorOf([&] { readJsonFile(dir_ / "missing.json"); }),
                HasSubstr("missing.json: cannot open file (no such file)"));
}

TEST_F(InputFiles, AFileLargerThanItsLimitIsRefused) {
    const fs::path p = write("big.csv", std::string(2000, 'x'));
    EXPECT_EQ(checkInputFile(p, 2000), 2000u);
    EXPECT_THAT(errorOf([&] { readInputFile(p, 1000); }),
                HasSubstr("big.csv: the file is 0.0 MiB, more than the limit"));
    EXPECT_EQ(readInputFile(p, 2000).size(), 2000u);
}

TEST_F(InputFiles, AFilePathInJsonMustBeARegularFile) {
    const Json j = {{"file", dir_.string()}};
    const JsonSource source{"scene.json", "."};
    const JsonReader r(j, "", source);
    EXPECT_THAT(errorOf([&] { r.filePath("file"); }),
                HasSubstr("scene.json: file: " + dir_.string() + ": is a directory"));
}

TEST(JsonBounds, DeepNestingIsRefusedWithoutCrashing) {
    const int levels = 100000;
    const std::string text =
        "{\"camera\": " + std::string(levels, '[') + std::string(levels, ']') + "}";
    const JsonSource source{"deep.json", "."};
    EXPECT_THAT(errorOf([&] { parseJsonText(text, source); }),
                HasSubstr("deep.json: malformed JSON: arrays and objects nested deeper than 64"));
    // Up to the limit is legal JSON.
    const std::string ok = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    EXPECT_NO_THROW(parseJsonText(ok, source));
}

TEST(JsonBounds, MessagesEchoAShortPrefixOfAValue) {
    Json big = Json::array();
    for (int i = 0; i < 10000; ++i)
        big.push_back("element");
    const Json j = {{"name", big}, {"flag", big}, {"count", big}, {"roughness", big}};
    const JsonSource source{"scene.json", "."};
    const JsonReader r(j, "", source);
    for (const std::string& message :
         {errorOf([&] { r.string("name", ""); }), errorOf([&] { r.boolean("flag", false); }),
          errorOf([&] { r.integer("count", 0, 0, 9); }),
          errorOf([&] { r.number("roughness", 0.0); }),
          errorOf([&] { JsonReader(big, "x", source).expectObject(); })}) {
        EXPECT_THAT(message, HasSubstr("[\"element\",\"element\""));
        EXPECT_THAT(message, HasSubstr("..."));
        EXPECT_LT(message.size(), 200u) << message;
    }
}

// JSON keeps only one of two equal keys (nlohmann: the last): a scene that sets a key twice
// means one of them by mistake, so the reader refuses it with the key's JSON path.
TEST(JsonDuplicateKeys, AreRefusedWithTheirPath) {
    const JsonSource source{"scene.json", "."};
    EXPECT_EQ(errorOf([&] { parseJsonText(R"({"spp": 4, "spp": 8})", source); }),
              "scene.json: spp: duplicate key: expected each key once in an object (JSON keeps "
              "only one of them)");
    EXPECT_THAT(errorOf([&] {
                    parseJsonText(R"({"materials": {"red": {"type": "lambert"}},
                                     "shapes": [{"type": "sphere"},
                                                {"type": "mesh", "faces": [[0, 1, 2]],
                                                 "positions": [], "material": "a",
                                                 "material": "b"}]})",
                                  source);
                }),
                HasSubstr("scene.json: shapes[1].material: duplicate key"));
    EXPECT_THAT(errorOf([&] { parseJsonText(R"([1, {"a": {"b": 1, "b": 2}}])", source); }),
                HasSubstr("scene.json: [1].a.b: duplicate key"));
    // Equal keys in different objects, and equal values, are fine.
    EXPECT_EQ(errorOf([&] {
                  parseJsonText(R"({"a": {"x": 1}, "b": {"x": 1}, "c": [{"x": 1}, {"x": 2}]})",
                                source);
              }),
              "(accepted)");
}

}  // namespace
}  // namespace lamina
