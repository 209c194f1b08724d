// libFuzzer target: the lens file reader (a realistic camera's lens system) on arbitrary bytes,
// and the lens system a file that reads builds (focusing, the exit pupil's bounds): bounded in
// time whatever the interfaces.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/lens_file.h"
#include "lamina/scene/lens_system.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".dat");
    return lamina::fuzz::readOrRefuse([&] {
        const lamina::render::LensSystem lens(lamina::render::readLensFile(file.path()), 0.004, 10,
                                              0.035);
        (void)lens.sampleExitPupil({0.001, 0.002}, {0.5, 0.5});
    });
}
