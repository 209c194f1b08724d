// libFuzzer target: the RGL material file reader (a `measured` material's tensor file) on
// arbitrary bytes, through the table it builds.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/scene/rgl_bsdf_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".bsdf");
    return lamina::fuzz::readOrRefuse([&] {
        const lamina::MeasuredBsdfTable table = lamina::render::readRglBsdfFile(file.path());
        // A table that was accepted is evaluated and sampled once: no crash, no NaN.
        const lamina::Vec3d wo(0.3, 0.2, 0.932738), wi(-0.4, 0.1, 0.910494);
        if (const auto l = table.lookup(wo, wi)) (void)table.rgbValue(*l, 1);
        (void)table.sample(wo, lamina::Vec2d(0.3, 0.7));
    });
}
