// libFuzzer target: the PLY reader (ASCII and binary) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/mesh_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".ply");
    return lamina::fuzz::readOrRefuse([&] {
        lamina::render::MeshDesc mesh;
        lamina::render::readPly(file.path(), mesh);
    });
}
