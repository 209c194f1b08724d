// libFuzzer target: the lamina JSON scene loader on arbitrary text. Relative file references
// resolve against an empty directory, so the loader's file checks are exercised too.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "fuzz_input_file.h"
#include "lamina/core/json_reader.h"
#include "lamina/scene/scene_description.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path directory = [] {
        auto d = std::filesystem::temp_directory_path() / "lamina-fuzz-scene-dir";
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::string text(reinterpret_cast<const char*>(data), size);
    lamina::JsonSource source;
    source.name = "fuzz.json";
    source.directory = directory;
    return lamina::fuzz::readOrRefuse([&] { (void)lamina::render::parseScene(text, source); });
}
