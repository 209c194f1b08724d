// libFuzzer target: the OBJ reader (tinyobjloader and what lamina makes of its output) on
// arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/mesh_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".obj");
    return lamina::fuzz::readOrRefuse([&] {
        lamina::render::MeshDesc mesh;
        lamina::render::readObj(file.path(), mesh);
    });
}
