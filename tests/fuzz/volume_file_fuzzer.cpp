// libFuzzer target: the grid files of other renderers (volume_files.h). The first byte chooses:
// odd, the rest is a Mitsuba .vol file as it is; even, the rest edits a valid NanoVDB file made
// at start-up with NanoVDB's own builder (a truncation length, then (offset, byte) pairs), so
// that the fuzzer reaches the tree walk behind the headers, where a damaged node offset would
// make a trusting reader read outside the file.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "fuzz_input_file.h"
#include "lamina/scene/volume_files.h"

#ifdef LAMINA_HAS_NANOVDB
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>
#endif

namespace {

std::string validNanoVdb() {
#ifdef LAMINA_HAS_NANOVDB
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    auto acc = builder.getAccessor();
    for (int k = 0; k < 3; ++k)
        for (int j = -1; j < 2; ++j)
            for (int i = 6; i < 10; ++i)
                acc.setValue(nanovdb::Coord(i, j, k), float(i + j + k) + 0.5f);
    const auto handle = builder.getHandle<>(0.25, nanovdb::Vec3d(1, 0, -1), "density");
    const std::string path =
        (std::filesystem::temp_directory_path() / "lamina-fuzz-seed.nvdb").string();
    nanovdb::io::writeGrid(path, handle);
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(path);
    return bytes;
#else
    return {};
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    if (data[0] & 1) {
        const lamina::fuzz::InputFile file(data + 1, size - 1, ".vol");
        return lamina::fuzz::readOrRefuse([&] { lamina::render::readMitsubaVolume(file.path()); });
    }
    static const std::string valid = validNanoVdb();
    if (valid.empty()) return 0;
    std::string bytes = valid;
    std::size_t at = 1;
    if (size >= 5) {
        std::uint32_t keep = 0;
        for (int i = 0; i < 4; ++i)
            keep = keep << 8 | data[1 + i];
        // Mostly whole files: a truncation when the top bit is set.
        if (keep & 0x80000000u) bytes.resize((keep & 0x7fffffffu) % (bytes.size() + 1));
        at = 5;
    }
    for (; at + 5 <= size && !bytes.empty(); at += 5) {
        std::uint32_t offset = 0;
        for (int i = 0; i < 4; ++i)
            offset = offset << 8 | data[at + std::size_t(i)];
        bytes[offset % bytes.size()] = char(data[at + 4]);
    }
    const lamina::fuzz::InputFile file(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                       bytes.size(), ".nvdb");
    return lamina::fuzz::readOrRefuse(
        [&] { lamina::render::readNanoVdbFile(file.path(), "density"); });
}
