#include "lamina/integrators/integrator.h"

#include <stdexcept>

#include "lamina/integrators/bdpt_integrator.h"
#include "lamina/integrators/light_integrator.h"
#include "lamina/integrators/path_integrator.h"
#include "lamina/render/renderer.h"

namespace lamina::render {

CameraSample sampleCamera(const PixelFilter& filter, const Camera& camera, PixelSampler& sampler,
                          int x, int y) {
    const auto fs = filter.sample(sampler.getPixel2D());
    const Vec2f lens = sampler.get2DIfUsed(!camera.isPinhole());
    const Vec2f raster(float(x) + 0.5f + fs.offset.x, float(y) + 0.5f + fs.offset.y);
    return {raster, lens, fs.weight};
}

template <SpectrumType S>
std::unique_ptr<Integrator<S>> makeIntegrator(const IntegratorSetup<S>& setup) {
    // Every caller of the renderer checks first (with its mode: renderScene refuses media in
    // the polarised mode); this keeps a direct caller from rendering media as vacuum.
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

template std::unique_ptr<Integrator<Rgb<float>>> makeIntegrator(const IntegratorSetup<Rgb<float>>&);
template std::unique_ptr<Integrator<SampledSpectrum<float>>> makeIntegrator(
    const IntegratorSetup<SampledSpectrum<float>>&);
template std::unique_ptr<Integrator<PolarisedSpectrum>> makeIntegrator(
    const IntegratorSetup<PolarisedSpectrum>&);

}  // namespace lamina::render
