// Raw incoherent Embree closest-hit rays per second on the geometry of a scene (default: the
// Cornell box), the limit the path tracer's ray rate is measured against:
//   build/benchmarks/lamina_embree_limit [scenes/cornell-box.json] [threads] [rays]
// `lamina bench SCENE --embree-limit` prints the same figure beside the path tracer's rays/s,
// measured in the same run (docs/performance.md).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "lamina/geometry/embree_limit.h"
#include "lamina/scene/scene_description.h"

int main(int argc, char** argv) {
    try {
        const std::string file = argc > 1 ? argv[1] : "scenes/cornell-box.json";
        const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
        const std::uint64_t rays = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1u << 22;
        const auto scene = lamina::render::loadScene(file);
        const auto rate = lamina::render::measureRawRayRate(scene, threads, rays);
        std::printf("%s: %d threads, %llu incoherent rays (%.1f%% hit), %.4g closest-hit rays/s\n",
                    file.c_str(), threads, static_cast<unsigned long long>(rate.rays),
                    100.0 * double(rate.hits) / double(rate.rays), rate.raysPerSecond());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lamina_embree_limit: error: %s\n", e.what());
        return 1;
    }
}
