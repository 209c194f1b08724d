// libFuzzer target: the pbrt-v4 importer (tokenizer, parser and translation) on arbitrary
// bytes. Includes and file names in the input resolve against the temporary directory.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/interchange/scene_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".pbrt");
    return lamina::fuzz::readOrRefuse(
        [&] { lamina::render::importScene(file.path(), file.path().parent_path()); });
}
