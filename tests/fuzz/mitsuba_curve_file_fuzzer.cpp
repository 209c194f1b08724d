// libFuzzer target: the reader of Mitsuba 3's curve files (`bsplinecurve` and `linearcurve`
// control points, "x y z radius" lines) on arbitrary bytes, as B-spline and as polyline files.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input_file.h"
#include "lamina/interchange/mitsuba_curve_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lamina::fuzz::InputFile file(data, size, ".txt");
    for (const std::size_t minPoints : {std::size_t(4), std::size_t(2)})
        lamina::fuzz::readOrRefuse([&] {
            const auto curves = lamina::render::readMitsubaCurveFile(file.path(), minPoints);
            // What was accepted holds its promises: no curve too short, finite, radius >= 0.
            for (const auto& curve : curves) {
                if (curve.size() < minPoints) std::abort();
                for (const auto& c : curve)
                    if (!std::isfinite(c.position.x + c.position.y + c.position.z) ||
                        !(c.radius >= 0))
                        std::abort();
            }
        });
    return 0;
}
