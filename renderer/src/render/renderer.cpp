#include "lamina/render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>

#include "lamina/render/path_integrator.h"
#include "lamina/render/pixel_filter.h"

namespace lamina::render {

std::atomic<bool>& renderInterruptFlag() {
    static std::atomic<bool> flag{false};
    return flag;
}

namespace {

constexpr int kTileSize = 16;

template <SpectrumType S>
RenderResult renderWithMode(const SceneDesc& scene, const RenderOptions& options,
                            const RenderSettings& settings, int width, int height,
                            const std::function<void(const RenderProgress&)>& progress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    RenderResult result;
    result.settings = settings;
    result.modeName = RenderMode<S>::kName;
    result.film = std::make_unique<Film>(width, height, RenderMode<S>::kFilmSpace);
    Film& film = *result.film;

    Geometry geometry(scene);
    const LightSet lights(scene, geometry, settings.uniformLightSelection);
    const Camera camera(scene.camera, width, height);
    const PixelFilter filter(scene.film);
    const RenderMode<S> mode(scene);
    const SceneContext context{scene, geometry, lights, camera};
    const PathIntegrator<S> integrator(context, mode, settings);

    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    std::atomic<std::uint64_t> rays{0};
    std::atomic<std::uint64_t> pixelsDone{0};
    const bool timed = options.seconds.has_value();
    const int targetSpp = timed ? std::numeric_limits<int>::max() : settings.spp;
    const auto elapsed = [&] {
        return std::chrono::duration<double>(Clock::now() - start).count();
    };

    int done = 0, passes = 0;
    auto& interrupted = renderInterruptFlag();
    while (done < targetSpp && !interrupted.load()) {
        // Passes double in size (1, 1, 2, 4, ... up to 64 spp), so early progress is quick
        // and an interruption or a time limit loses little work.
        const int passSpp = std::min({targetSpp - done, std::max(1, std::min(done, 64))});
        const int first = done;
        tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const auto& range) {
            PathStatistics stats;
            for (int tile = range.begin(); tile != range.end(); ++tile) {
                const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, width),
                          y1 = std::min(y0 + kTileSize, height);
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) {
                        for (int s = first; s < first + passSpp; ++s) {
                            PixelSampler sampler(settings.sampler, settings.seed, x, y,
                                                 std::uint32_t(s));
                            auto path = mode.startPath(sampler);
                            const auto fs = filter.sample(sampler.get2D());
                            const Vec2f lens = sampler.get2D();
                            const auto ray = camera.generateRay(
                                float(x) + 0.5f + fs.offset.x, float(y) + 0.5f + fs.offset.y, lens);
                            PixelAovs aovs;
                            const S L =
                                integrator.radiance(ray.origin, ray.direction, sampler, path, stats,
                                                    options.aovs ? &aovs : nullptr);
                            film.addSample(x, y, mode.filmValue(L, path), fs.weight);
                            if (options.aovs) film.addAovs(x, y, aovs);
                        }
                    }
                pixelsDone.fetch_add(std::uint64_t((x1 - x0) * (y1 - y0)) * passSpp);
            }
            rays.fetch_add(stats.rays);
        });
        done += passSpp;
        ++passes;
        if (progress) {
            RenderProgress p;
            p.seconds = elapsed();
            p.passesDone = passes;
            p.sppDone = done;
            p.fraction = timed ? std::min(1.0, p.seconds / *options.seconds)
                               : double(done) / double(targetSpp);
            progress(p);
        }
        if (timed && elapsed() >= *options.seconds) break;
    }
    result.spp = done;
    result.partial = interrupted.load() && !timed;
    result.seconds = elapsed();
    result.rays = rays.load();
    result.paths = pixelsDone.load();
    return result;
}

}  // namespace

RenderResult renderScene(const SceneDesc& scene, const RenderOptions& options,
                         const std::function<void(const RenderProgress&)>& progress) {
    RenderSettings settings = scene.settings;
    if (options.spp) settings.spp = *options.spp;
    if (options.seed) settings.seed = *options.seed;
    if (options.maxDepth) settings.maxDepth = *options.maxDepth;
    if (options.sampler) settings.sampler = *options.sampler;
    int width = scene.film.width, height = scene.film.height;
    if (options.resolution) std::tie(width, height) = *options.resolution;

    std::optional<tbb::global_control> threads;
    if (options.threads > 0)
        threads.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
    if (options.mode == RenderModeKind::Spectral)
        return renderWithMode<SampledSpectrum<float>>(scene, options, settings, width, height,
                                                      progress);
    return renderWithMode<Rgb<float>>(scene, options, settings, width, height, progress);
}

}  // namespace lamina::render
