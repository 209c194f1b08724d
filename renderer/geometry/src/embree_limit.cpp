#include "lamina/geometry/embree_limit.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <vector>

#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/geometry/geometry.h"

namespace lamina::render {

namespace {

struct RayDesc {
    Vec3f origin, direction;
};

}  // namespace

RawRayRate measureRawRayRate(const SceneDesc& scene, int threads, std::uint64_t rays, int repeats) {
    const Geometry geometry(scene);
    // The rays start inside the box of everything (instances included), as a path's bounces do.
    const Vec3f lo = geometry.boundsLo(), hi = geometry.boundsHi();
    std::vector<RayDesc> batch(rays);
    Pcg32 rng(12345);
    for (RayDesc& r : batch) {
        const Vec3f u(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        r.origin = lo + u * (hi - lo);
        r.direction = squareToUniformSphere(Vec2f(rng.nextFloat(), rng.nextFloat()));
    }
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    RawRayRate best;
    for (int repeat = 0; repeat < repeats; ++repeat) {
        std::atomic<std::uint64_t> found{0};
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 4096),
                              [&](const auto& range) {
                                  RTCIntersectContext context;
                                  rtcInitIntersectContext(&context);
                                  std::uint64_t local = 0;
                                  for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                      RTCRayHit rh{};
                                      const RayDesc& r = batch[i];
                                      rh.ray.org_x = r.origin.x;
                                      rh.ray.org_y = r.origin.y;
                                      rh.ray.org_z = r.origin.z;
                                      rh.ray.dir_x = r.direction.x;
                                      rh.ray.dir_y = r.direction.y;
                                      rh.ray.dir_z = r.direction.z;
                                      rh.ray.tnear = 0.0f;
                                      rh.ray.tfar = std::numeric_limits<float>::infinity();
                                      rh.ray.mask = ~0u;
                                      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                                      rtcIntersect1(geometry.embreeScene(), &context, &rh);
                                      local += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                                  }
                                  found.fetch_add(local);
                              });
        });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (best.seconds == 0 || seconds < best.seconds)
            best = {batch.size(), found.load(), seconds};
    }
    return best;
}

}  // namespace lamina::render
