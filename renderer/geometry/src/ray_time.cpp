#include "lamina/geometry/ray_time.h"

namespace lamina::render {

namespace {
thread_local float tRayTime = 0.0f;
}  // namespace

float currentRayTime() {
    return tRayTime;
}

RayTimeScope::RayTimeScope(float time) : previous_(tRayTime) {
    tRayTime = time;
}

RayTimeScope::~RayTimeScope() {
    tRayTime = previous_;
}

}  // namespace lamina::render
