// libFuzzer target: the Mitsuba serialized mesh reader on arbitrary bytes, for its first mesh
// and, through the table at the file's end, its second.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/mesh_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".serialized");
    lamina::fuzz::readOrRefuse([&] {
        lamina::render::MeshDesc mesh;
        lamina::render::readSerialized(file.path(), 0, mesh);
    });
    return lamina::fuzz::readOrRefuse([&] {
        lamina::render::MeshDesc mesh;
        lamina::render::readSerialized(file.path(), 1, mesh);
    });
}
