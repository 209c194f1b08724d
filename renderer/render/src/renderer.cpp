#include "lamina/render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <limits>
#include <optional>

#include "lamina/core/error.h"
#include "lamina/geometry/ray_time.h"
#include "lamina/integrators/integrator.h"
#include "lamina/integrators/medium_emitters.h"
#include "lamina/render/global_sobol_net.h"
#include "lamina/render/pass_schedule.h"
#include "lamina/render/render_limits.h"
#include "lamina/render/render_memory.h"

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
    result.modeName = kRenderModeNames.name(options.mode);
    if (settings.integrator != IntegratorKind::Path && options.aovs)
        throw InputError("AOVs are written by the path integrator only");
    const PixelBounds window = options.crop.value_or(PixelBounds{0, width, 0, height});
    result.film = std::make_unique<Film>(width, height, window, RenderMode<S>::kFilmSpace);
    Film& film = *result.film;
    film.setResponse(FilmResponse(scene.film, RenderMode<S>::kFilmSpace));
    if (options.mode == RenderModeKind::Rgb && scene.film.whiteBalance > 0)
        result.warnings.push_back(
            "RGB mode white-balances the Rec.709 colours its paths carry (CIE 1931 XYZ of "
            "each sample); spectral mode integrates the spectra against the sensor's curves "
            "(--mode spectral)");

    Geometry geometry(scene);
    const LightSet lights(scene, geometry, settings.lightSelection);
    const Camera camera(scene.camera, width, height);
    const Vec3f imageRight = camera.imageRight();
    if constexpr (std::is_same_v<S, PolarisedSpectrum>) film.enableStokes();
    const PixelFilter filter(scene.film);
    const RenderMode<S> mode(scene, settings.seed);
    const SceneContext context{scene, geometry, lights, camera};
    if (options.strategies && settings.integrator == IntegratorKind::Bdpt)
        result.strategies = std::make_unique<StrategyImages>(width, height);
    const auto integrator = makeIntegrator<S>({context, mode, settings, filter, options.ablations,
                                               options.aovs, result.strategies.get()});

    const bool splats = integrator->splats();
    constexpr bool kPolarised = std::is_same_v<S, PolarisedSpectrum>;
    if (options.spectralBins > 0)
        film.enableSpectralFilm(SpectralBins{options.spectralBins}, kPolarised ? 4 : 1, splats);
    const SpectralFilm* spectralFilm = film.spectralFilm();
    // Particles from every pixel may land in a crop, so a splatting integrator traces the
    // whole film (the film keeps what falls in its window); the path integrator only the crop.
    const PixelBounds traced = splats ? PixelBounds{0, width, 0, height} : window;
    const int tilesX = (traced.width() + kTileSize - 1) / kTileSize;
    const int tilesY = (traced.height() + kTileSize - 1) / kTileSize;
    std::atomic<std::uint64_t> rays{0};
    std::atomic<std::uint64_t> pixelsDone{0};
    const bool timed = options.seconds.has_value();
    // Render time excludes the time spent in the progress callback (which may, for example,
    // measure the error of the image so far).
    double callbackSeconds = 0;
    const auto elapsed = [&] {
        return std::chrono::duration<double>(Clock::now() - start).count() - callbackSeconds;
    };

    // sobol-global's film positions: one net over the whole image (a crop is a window of it).
    std::optional<GlobalSobolNet> globalNet;
    if (settings.sampler == SamplerKind::SobolGlobal) globalNet.emplace(width, height);
    const GlobalSobolNet* net = globalNet ? &*globalNet : nullptr;

    // One sample of pixel (x, y): the integrator's camera-side estimate goes to the pixel, its
    // splats (light, bdpt) anywhere on the film.
    const bool moves = scene.hasMotion();
    const std::array<double, 2> shutter = scene.camera.shutter;
    const auto renderSample = [&](int x, int y, const PixelSeed& pixelSeed, int s,
                                  PathStatistics& stats) {
        PixelSampler sampler(settings.sampler, pixelSeed, std::uint32_t(s), net);
        auto path = mode.startPath(sampler);
        // Motion blur: one time per sample, uniform over the shutter, for every ray of it
        // (ray_time.h). A scene where nothing moves draws no number, so its images keep
        // their bits.
        std::optional<RayTimeScope> sampleTime;
        if (moves)
            sampleTime.emplace(
                float(shutter[0] + double(sampler.get1D()) * (shutter[1] - shutter[0])));
        const auto estimate = integrator->sample({x, y, sampler, path, film, stats});
        if (!estimate) return;
        if constexpr (kPolarised) {
            const auto stokes =
                mode.imageStokes(estimate->value, estimate->rayDirection, imageRight);
            if (spectralFilm) {
                const SpectralFilmSample bins =
                    mode.filmSpectrum(stokes, path, spectralFilm->bins());
                film.addPolarisedSample(x, y, mode.filmStokes(stokes, path), estimate->filterWeight,
                                        &bins);
            } else {
                film.addPolarisedSample(x, y, mode.filmStokes(stokes, path),
                                        estimate->filterWeight);
            }
        } else if constexpr (std::is_same_v<S, SampledSpectrum<float>>) {
            if (spectralFilm) {
                const SpectralFilmSample bins =
                    mode.filmSpectrum(estimate->value, path, spectralFilm->bins());
                film.addSample(x, y, mode.filmValue(estimate->value, path), estimate->filterWeight,
                               &bins);
            } else {
                film.addSample(x, y, mode.filmValue(estimate->value, path), estimate->filterWeight);
            }
        } else {
            film.addSample(x, y, mode.filmValue(estimate->value, path), estimate->filterWeight);
        }
        if (estimate->aovs) film.addAovs(x, y, *estimate->aovs);
    };
    // Samples [first, first + count) of every pixel, tile by tile in parallel.
    const auto renderSamples = [&](int first, int count) {
        tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const auto& range) {
            PathStatistics stats;
            for (int tile = range.begin(); tile != range.end(); ++tile) {
                const int x0 = traced.x0 + (tile % tilesX) * kTileSize,
                          y0 = traced.y0 + (tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, traced.x1),
                          y1 = std::min(y0 + kTileSize, traced.y1);
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) {
                        const PixelSeed pixelSeed(settings.seed, x, y);
                        for (int s = first; s < first + count; ++s)
                            renderSample(x, y, pixelSeed, s, stats);
                    }
                pixelsDone.fetch_add(std::uint64_t((x1 - x0) * (y1 - y0)) * count);
            }
            rays.fetch_add(stats.rays);
        });
    };

    PassSchedule schedule(settings.spp, options.seconds);
    const int first = options.samples ? options.samples->first : 0;
    int done = 0, passes = 0;
    auto& interrupted = renderInterruptFlag();
    // The first pass always runs, so an interrupted render still has an image to write; an
    // interruption stops the loop after the pass in flight. `complete`: the requested samples
    // or time were used up (a render interrupted before that is partial, timed or not).
    bool complete = false;
    while (true) {
        if (done > 0 && interrupted.load()) break;
        int passSpp = schedule.next(done, elapsed());
        // A sample range bounds a timed render too.
        if (options.samples) passSpp = std::min(passSpp, options.samples->count - done);
        if (passSpp == 0) {
            complete = true;
            break;
        }
        const double passStart = elapsed();
        if (!splats) {
            renderSamples(first + done, passSpp);
        } else {
            // Splatting integrators run one sample per pixel at a time: each such iteration
            // (width x height light paths) is one sample of the splat layer's per-pixel
            // variance.
            for (int s = first + done; s < first + done + passSpp; ++s) {
                renderSamples(s, 1);
                film.endSplatIteration(1.0 / (double(width) * double(height)));
            }
        }
        schedule.record(passSpp, elapsed() - passStart);
        done += passSpp;
        ++passes;
        if (progress) {
            RenderProgress p;
            p.seconds = elapsed();
            p.passesDone = passes;
            p.sppDone = done;
            p.fraction = timed ? std::min(1.0, p.seconds / *options.seconds)
                               : double(done) / double(settings.spp);
            p.film = &film;
            const auto before = Clock::now();
            progress(p);
            callbackSeconds += std::chrono::duration<double>(Clock::now() - before).count();
        }
    }
    result.spp = done;
    result.firstSample = first;
    result.partial = !complete;
    result.seconds = elapsed();
    result.rays = rays.load();
    result.paths = pixelsDone.load();
    return result;
}

RenderOptions withCrop(const RenderOptions& options, const PixelBounds& crop) {
    RenderOptions o = options;
    o.crop = crop;
    return o;
}

}  // namespace

void checkMedia(const SceneDesc& scene, RenderModeKind mode, IntegratorKind integrator) {
    // Every caller checks here before it renders: so does the camera.
    if (scene.camera.lensSystem && integrator != IntegratorKind::Path)
        throw InputError(scene.file.string() +
                         ": camera.type: the realistic camera renders with the path integrator "
                         "only (light tracing and BDPT connect to the lens by its importance, "
                         "which a lens system has in no closed form); use \"integrator\": "
                         "{\"type\": \"path\"}");
    if (!scene.hasMedia()) return;
    // Light tracing and BDPT start particles in an emitting medium's volume: one that fills
    // space cannot be sampled (the integrators refuse the other media that reach infinity,
    // which only the geometry tells: MediumEmitters).
    if (integrator == IntegratorKind::Light || integrator == IntegratorKind::Bdpt)
        for (int i = 0; i < int(scene.media.size()); ++i)
            if (emissionFillsSpace(scene, i)) refuseUnboundedEmission(scene, i);
    if (mode == RenderModeKind::Polarised)
        throw InputError(scene.file.string() +
                         ": media: the polarised mode does not render media yet; use --mode "
                         "spectral or rgb");
}

RenderSettings resolveRenderSettings(const SceneDesc& scene, const RenderOptions& options) {
    RenderSettings settings = scene.settings;
    if (options.spp) settings.spp = *options.spp;
    if (options.seed) settings.seed = *options.seed;
    if (options.maxDepth) settings.maxDepth = *options.maxDepth;
    if (options.sampler) settings.sampler = *options.sampler;
    if (options.integrator) settings.integrator = *options.integrator;
    if (options.mis) settings.mis = *options.mis;
    if (options.lightSelection) settings.lightSelection = *options.lightSelection;
    if (options.samples) settings.spp = options.samples->count;
    return settings;
}

RenderResult renderScene(const SceneDesc& scene, const RenderOptions& options,
                         const std::function<void(const RenderProgress&)>& progress) {
    const RenderSettings settings = resolveRenderSettings(scene, options);
    if (options.samples) {
        const SampleRange& r = *options.samples;
        if (r.first < 0 || r.count < 1 || r.count > std::numeric_limits<int>::max() - r.first)
            throw InputError("--samples " + std::to_string(r.first) + ":" +
                             std::to_string(r.count) +
                             ": expected FIRST >= 0 and COUNT >= 1 with FIRST + COUNT < 2^31");
    }
    if (options.spectralBins < 0 || options.spectralBins > kMaxSpectralFilmBins)
        throw InputError("--spectral-film " + std::to_string(options.spectralBins) +
                         ": expected 1 to " + std::to_string(kMaxSpectralFilmBins) + " bins");
    if (options.spectralBins > 0 && options.mode == RenderModeKind::Rgb)
        throw InputError(
            "--spectral-film: the rgb mode carries no spectrum; use --mode spectral "
            "or polarised");
    int width = scene.film.width, height = scene.film.height;
    if (options.resolution) std::tie(width, height) = *options.resolution;
    // The scene's crop, unless the command line gives one (a shard of a render: the whole
    // image's pixels).
    if (!options.crop && scene.film.crop && !options.resolution) {
        if (options.strategies)
            throw InputError(scene.file.string() +
                             ": film.crop: --strategies renders the whole film (remove the crop)");
        return renderScene(scene, withCrop(options, *scene.film.crop), progress);
    }
    if (options.crop) {
        const PixelBounds& c = *options.crop;
        if (c.x0 < 0 || c.y0 < 0 || c.x1 > width || c.y1 > height || c.x0 >= c.x1 || c.y0 >= c.y1)
            throw InputError("--crop " + std::to_string(c.x0) + "," + std::to_string(c.x1) + "," +
                             std::to_string(c.y0) + "," + std::to_string(c.y1) +
                             ": expected 0 <= X0 < X1 <= " + std::to_string(width) +
                             " and 0 <= Y0 < Y1 <= " + std::to_string(height) + " (the film)");
        if (options.strategies) throw InputError("--strategies renders the whole film: no --crop");
    }
    const int filmWidth = options.crop ? options.crop->width() : width;
    const int filmHeight = options.crop ? options.crop->height() : height;
    const int spectralValues =
        options.spectralBins * (options.mode == RenderModeKind::Polarised ? 4 : 1);
    checkRenderMemory(
        estimateRenderMemory(filmWidth, filmHeight, options.aovs,
                             options.strategies && settings.integrator == IntegratorKind::Bdpt,
                             spectralValues, settings.integrator != IntegratorKind::Path),
        width, height,
        options.resolution ? "--resolution" : scene.file.string() + ": film.resolution");

    checkMedia(scene, options.mode, settings.integrator);
    if (scene.camera.analyserDegrees && options.mode != RenderModeKind::Polarised)
        throw InputError(scene.file.string() +
                         ": camera.analyser: a polariser in front of the lens needs --mode "
                         "polarised (the " +
                         std::string(kRenderModeNames.name(options.mode)) +
                         " mode renders unpolarised light)");
    std::optional<tbb::global_control> threads;
    if (options.threads > 0)
        threads.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
    if (options.mode == RenderModeKind::Polarised)
        return renderWithMode<PolarisedSpectrum>(scene, options, settings, width, height, progress);
    if (options.mode == RenderModeKind::Spectral)
        return renderWithMode<SampledSpectrum<float>>(scene, options, settings, width, height,
                                                      progress);
    return renderWithMode<Rgb<float>>(scene, options, settings, width, height, progress);
}

}  // namespace lamina::render
