// A render: the scene's acceleration structure, lights and camera, passes of samples over
// tiles in parallel (oneTBB), progress, and interruption (Ctrl-C finishes the pass in flight).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lamina/integrators/strategy_images.h"
#include "lamina/integrators/transport_ablations.h"
#include "lamina/render/film.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

enum class RenderModeKind { Rgb, Spectral, Polarised };
inline constexpr NameTable kRenderModeNames{std::array{
    NameEntry{RenderModeKind::Rgb, "rgb"}, NameEntry{RenderModeKind::Spectral, "spectral"},
    NameEntry{RenderModeKind::Polarised, "polarised"}}};

/// Sample indices [first, first + count) of every pixel (`render --samples FIRST:COUNT`).
struct SampleRange {
    int first = 0;
    int count = 0;
};

struct RenderOptions {
    RenderModeKind mode = RenderModeKind::Rgb;
    std::optional<int> spp;         ///< overrides the scene's
    std::optional<double> seconds;  ///< progressive passes until this much time has passed
    std::optional<std::uint64_t> seed;
    std::optional<int> maxDepth;
    std::optional<std::pair<int, int>> resolution;
    std::optional<SamplerKind> sampler;
    std::optional<IntegratorKind> integrator;
    std::optional<MisHeuristic> mis;
    std::optional<LightSelection> lightSelection;
    int threads = 0;    ///< 0: all cores
    bool aovs = false;  ///< path integrator only
    TransportAblations ablations;
    bool strategies = false;  ///< bdpt: keep per-(s, t) images (RenderResult::strategies)
    /// Renders only these sample indices (overrides spp; with `seconds`, at most `count`).
    std::optional<SampleRange> samples;
    /// Renders only these pixels of the film, with the numbers of the whole render: light
    /// particles still start from every pixel, so a crop saves only the path integrator time.
    std::optional<PixelBounds> crop;
    /// `render --spectral-film N`: the film also keeps N bins of spectral radiance over
    /// [360, 830] nm (spectral_film.h; 0: none). The spectral and polarised modes only.
    int spectralBins = 0;
};

struct RenderProgress {
    double fraction = 0;  ///< of the planned work (of the time budget with --time)
    double seconds = 0;   ///< rendering time, without the time spent in progress callbacks
    int passesDone = 0;
    int sppDone = 0;
    const Film* film = nullptr;  ///< the image so far (valid during the call)
};

struct RenderResult {
    std::unique_ptr<Film> film;
    int spp = 0;          ///< samples per pixel rendered
    int firstSample = 0;  ///< the index of the first (RenderOptions::samples)
    double seconds = 0;
    std::uint64_t rays = 0;
    std::uint64_t paths = 0;
    bool partial = false;                        ///< interrupted before the requested spp or time
    std::string modeName;                        ///< kRenderModeNames
    RenderSettings settings;                     ///< after command-line overrides
    std::unique_ptr<StrategyImages> strategies;  ///< with RenderOptions::strategies (bdpt)
    /// What the render approximated, one line each (the front ends print them).
    std::vector<std::string> warnings;
};

/// Set (from a signal handler) to stop after the pass in flight.
std::atomic<bool>& renderInterruptFlag();

/// Renders the scene. `progress` is called from the calling thread now and then.
/// Refuses a scene with media (SceneDesc::hasMedia) for what does not render it yet: the
/// light and bdpt integrators with a homogeneous emitting medium that fills space (the
/// camera's, bounded by no shape; the integrators refuse the others that reach infinity when
/// they are made), and the polarised mode (docs/media.md); and that a realistic camera is
/// rendered by the path integrator (realistic_camera.h). The
/// renderer calls it; experiments call it before they start work.
void checkMedia(const SceneDesc& scene, RenderModeKind mode, IntegratorKind integrator);

/// The settings a render of `scene` with `options` runs with: the scene's, overridden by the
/// options (RenderResult::settings).
RenderSettings resolveRenderSettings(const SceneDesc& scene, const RenderOptions& options);

RenderResult renderScene(const SceneDesc& scene, const RenderOptions& options,
                         const std::function<void(const RenderProgress&)>& progress = {});

}  // namespace lamina::render
