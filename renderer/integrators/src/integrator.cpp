#include "lamina/integrators/integrator.h"

#include <stdexcept>

#include "lamina/integrators/bdpt_integrator.h"
#include "lamina/integrators/light_integrator.h"
#include "lamina/integrators/path_integrator.h"
#include "lamina/render/renderer.h"

namespace lamina::render {

CameraSample sampleCamera(const PixelFilter& filter, const Camera& camera, PixelSampler& sampler,
                          int x, int y) {
    const auto fs = filter.sample(sampler.get2D());
    const Vec2f lens = sampler.get2DIfUsed(!camera.isPinhole());
    const Vec2f raster(float(x) + 0.5f + fs.offset.x, float(y) + 0.5f + fs.offset.y);
    return {raster, lens, fs.weight};
}

template <SpectrumType S>
std::unique_ptr<Integrator<S>> makeIntegrator(const IntegratorSetup<S>& setup) {
    // Every caller of the renderer checks first; this keeps a direct caller from rendering
    // media as vacuum (the mode matters only when polarised, below).
    checkMedia(setup.context.scene, RenderModeKind::Spectral, setup.settings.integrator);
    switch (setup.settings.integrator) {
        case IntegratorKind::Path:
            return std::make_unique<PathIntegrator<S>>(setup);
        case IntegratorKind::Light:
            return std::make_unique<LightIntegrator<S>>(setup);
        case IntegratorKind::Bdpt:
            return std::make_unique<BdptIntegrator<S>>(setup);
    }
    throw std::logic_error("makeIntegrator: an integrator kind without an integrator");
}

/// The polarised mode runs the path integrator: light tracing and BDPT need the adjoint
/// Mueller matrices (docs/polarisation.md), which they do not have yet.
template <>
std::unique_ptr<Integrator<PolarisedSpectrum>> makeIntegrator(
    const IntegratorSetup<PolarisedSpectrum>& setup) {
    checkModeAndIntegrator(RenderModeKind::Polarised, setup.settings.integrator);
    checkMedia(setup.context.scene, RenderModeKind::Polarised, setup.settings.integrator);
    return std::make_unique<PathIntegrator<PolarisedSpectrum>>(setup);
}

template std::unique_ptr<Integrator<Rgb<float>>> makeIntegrator(const IntegratorSetup<Rgb<float>>&);
template std::unique_ptr<Integrator<SampledSpectrum<float>>> makeIntegrator(
    const IntegratorSetup<SampledSpectrum<float>>&);

}  // namespace lamina::render
