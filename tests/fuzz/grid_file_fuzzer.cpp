// libFuzzer target: the lamina grid file reader (a grid medium's densities) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/grid_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".lgrid");
    return lamina::fuzz::readOrRefuse([&] { lamina::render::readGridFile(file.path()); });
}
