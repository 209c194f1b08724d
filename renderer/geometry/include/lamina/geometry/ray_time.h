// The time at which rays are cast, for motion blur (docs/scene-format.md, "Motion blur"). A
// pixel sample draws one time, uniform over the camera's shutter interval, and every ray of
// that sample -- the camera path, the light path of light tracing and BDPT, their shadow rays
// and connections -- is cast at it, so a path sees one instant of the scene. The renderer
// holds the time in a RayTimeScope around the sample; the integrators need not pass it along,
// because a sample is traced on one thread from start to end (no nested parallelism).
#pragma once

namespace lamina::render {

/// The instant of the sample being traced on this thread, in the scene's time: 0 is where
/// instances stand at their `transform`, 1 at their `transform_end` (0 outside any scope).
float currentRayTime();

/// Sets this thread's ray time for its lifetime and restores the previous one after.
class RayTimeScope {
  public:
    explicit RayTimeScope(float time);
    ~RayTimeScope();
    RayTimeScope(const RayTimeScope&) = delete;
    RayTimeScope& operator=(const RayTimeScope&) = delete;

  private:
    float previous_;
};

}  // namespace lamina::render
