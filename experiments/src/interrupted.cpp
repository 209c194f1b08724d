#include "lamina/experiments/interrupted.h"

namespace lamina::experiments {

void stopIfInterrupted() {
    if (render::renderInterruptFlag().load()) throw Interrupted();
}

render::RenderResult renderWhole(
    const render::SceneDesc& scene, const render::RenderOptions& options,
    const std::function<void(const render::RenderProgress&)>& progress) {
    stopIfInterrupted();
    render::RenderResult r = render::renderScene(scene, options, progress);
    stopIfInterrupted();  // also a render that ended complete while the signal came
    return r;
}

}  // namespace lamina::experiments
