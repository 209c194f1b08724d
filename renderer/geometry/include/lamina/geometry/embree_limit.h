// The ray rate Embree alone reaches on a scene's geometry: incoherent closest-hit rays
// (origins uniform in the bounding box of the shapes, directions uniform on the sphere,
// generated before the clock starts), traced with rtcIntersect1 over the same BVH the renderer
// builds (Geometry) and nothing else: no hit point, normals or shading. What the path tracer's
// rays/s (which include all of that) can be compared with, measured in the same process.
#pragma once

#include <cstdint>

#include "lamina/scene/scene_description.h"

namespace lamina::render {

struct RawRayRate {
    std::uint64_t rays = 0;  ///< traced in the best repeat
    std::uint64_t hits = 0;  ///< of those, the rays that hit a surface
    double seconds = 0;      ///< of the best repeat
    double raysPerSecond() const { return seconds > 0 ? double(rays) / seconds : 0.0; }
};

/// Traces `rays` rays `repeats` times on `threads` threads (0: all cores) and keeps the
/// fastest repeat (the least disturbed by other work on the machine).
RawRayRate measureRawRayRate(const SceneDesc& scene, int threads, std::uint64_t rays = 1u << 20,
                             int repeats = 5);

}  // namespace lamina::render
