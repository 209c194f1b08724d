// The one interface the renderer calls per pixel sample, and the factory that makes the
// integrator of the settings' kind. One pixel sample, from the camera to the film:
//   1. the renderer makes the pixel's sampler (seeded by seed, pixel and sample index) and
//      lets the render mode start a path (spectral mode draws its wavelengths);
//   2. Integrator::sample: path and bdpt draw a camera sample (a film position from the
//      pixel filter, a lens point) and trace from it; light and bdpt trace a particle from a
//      light and splat what reaches the lens on the film (Film::addSplat);
//   3. the camera-side estimate, if any, goes to the sample's pixel (Film::addSample, with
//      the mode's film value and the filter weight), its AOVs with it.
// An integrator that splats is run one sample per pixel at a time, each such iteration ending
// with Film::endSplatIteration (the splat layer's variance is estimated per iteration).
// The integrators are compiled for the render modes (Rgb<float>, SampledSpectrum<float>, and
// PolarisedSpectrum for those that are polarised).
#pragma once

#include <memory>
#include <optional>

#include "lamina/integrators/strategy_images.h"
#include "lamina/integrators/transport_ablations.h"
#include "lamina/lights/lights.h"
#include "lamina/render/camera.h"
#include "lamina/render/film.h"
#include "lamina/render/pixel_filter.h"
#include "lamina/render/render_mode.h"

namespace lamina::render {

/// The scene the integrators read and what the renderer built from it.
struct SceneContext {
    const SceneDesc& scene;
    const Geometry& geometry;
    const LightSet& lights;
    const Camera& camera;
};

struct PathStatistics {
    std::uint64_t rays = 0;  ///< closest-hit and shadow rays traced
};

/// Where a camera sample looks through: a film position drawn from the pixel filter around
/// the pixel's centre (filter importance sampling, pixel_filter.h) and a lens point.
struct CameraSample {
    Vec2f raster;        ///< film position, in pixels
    Vec2f lens;          ///< in [0, 1)^2
    float filterWeight;  ///< f / pdf of the film position
};

/// Draws the camera sample of pixel (x, y): the filter's two numbers, then the lens's two
/// (skipped for a pinhole, which has no use for them).
CameraSample sampleCamera(const PixelFilter& filter, const Camera& camera, PixelSampler& sampler,
                          int x, int y);

/// One sample of one pixel, as the renderer hands it to an integrator.
template <SpectrumType S>
struct PixelSample {
    int x, y;                            ///< the pixel
    PixelSampler& sampler;               ///< its random numbers, after the mode's own
    typename RenderMode<S>::Path& path;  ///< the mode's state of this sample's paths
    Film& film;                          ///< where splats go
    PathStatistics& stats;
};

/// What a pixel sample gives its own pixel: the camera side's estimate with its filter
/// weight, and first-hit AOVs when they were asked for.
template <SpectrumType S>
struct CameraEstimate {
    S value;
    float filterWeight;
    std::optional<PixelAovs> aovs;
    /// The camera ray's direction (the polarised mode turns the Stokes vector into the image
    /// frame about it).
    Vec3f rayDirection{0.0f, 0.0f, 1.0f};
};

template <SpectrumType S>
class Integrator {
  public:
    Integrator() = default;
    Integrator(const Integrator&) = delete;
    Integrator& operator=(const Integrator&) = delete;
    virtual ~Integrator() = default;

    /// True when samples splat (light, bdpt): the renderer then takes one sample per pixel
    /// per splat iteration.
    virtual bool splats() const = 0;

    /// Takes one pixel sample: returns its camera-side estimate (path, bdpt; nothing for
    /// light) and splats on `sample.film` (light, bdpt).
    virtual std::optional<CameraEstimate<S>> sample(const PixelSample<S>& sample) const = 0;
};

/// What an integrator is built from (each takes what it uses). The references must outlive
/// the integrator.
template <SpectrumType S>
struct IntegratorSetup {
    SceneContext context;
    const RenderMode<S>& mode;
    RenderSettings settings;  ///< the integrator's kind, depth, Russian roulette, MIS
    const PixelFilter& filter;
    TransportAblations ablations;          ///< light and bdpt; all three through media
    bool aovs = false;                     ///< path only
    StrategyImages* strategies = nullptr;  ///< bdpt only, optional
};

/// The integrator of `setup.settings.integrator`.
template <SpectrumType S>
std::unique_ptr<Integrator<S>> makeIntegrator(const IntegratorSetup<S>& setup);

}  // namespace lamina::render
