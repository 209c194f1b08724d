// libFuzzer target: the Mitsuba 3 XML importer (document reading and translation) on arbitrary
// bytes. The input is a file of its own empty directory, so includes and file parameters
// resolve against nothing but the input itself (an include of it nests until refused).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_input_file.h"
#include "lamina/interchange/scene_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path directory = [] {
        auto d = std::filesystem::temp_directory_path() /
                 ("lamina-fuzz-mitsuba-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::filesystem::path file = directory / "scene.xml";
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    return lamina::fuzz::readOrRefuse([&] { (void)lamina::render::importScene(file, directory); });
}
