// Throughput of eval and sample per BSDF model, in float (the renderer's precision).
#include <benchmark/benchmark.h>

#include "lamina/bsdf/diffuse.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

template <typename B>
void benchEval(benchmark::State& state, const B& bxdf) {
    Pcg32 rng(1);
    const Vec3f wo = glm::normalize(Vec3f(0.3f, 0.2f, 0.9f));
    for (auto _ : state) {
        const Vec3f wi =
            glm::normalize(Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f));
        benchmark::DoNotOptimize(bxdf.eval(wo, wi, TransportMode::Radiance));
    }
}

template <typename B>
void benchSample(benchmark::State& state, const B& bxdf) {
    Pcg32 rng(1);
    const Vec3f wo = glm::normalize(Vec3f(0.3f, 0.2f, 0.9f));
    for (auto _ : state)
        benchmark::DoNotOptimize(
            bxdf.sample(wo, rng.nextFloat(), rng.nextFloat2(), TransportMode::Radiance));
}

void BM_LambertEval(benchmark::State& s) {
    benchEval(s, DiffuseBxdf<Rgbf>(Rgbf(0.5f)));
}
void BM_LambertSample(benchmark::State& s) {
    benchSample(s, DiffuseBxdf<Rgbf>(Rgbf(0.5f)));
}
BENCHMARK(BM_LambertEval);
BENCHMARK(BM_LambertSample);

}  // namespace
}  // namespace lamina

BENCHMARK_MAIN();
