// libFuzzer target: the lens file reader (a realistic camera's lens system) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/lens_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".dat");
    return lamina::fuzz::readOrRefuse([&] { lamina::render::readLensFile(file.path()); });
}
