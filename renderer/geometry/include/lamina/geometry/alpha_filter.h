// Alpha cut-outs as Embree filter functions: a hit on a shape whose alpha is below 1 is
// rejected (the ray goes on through it) unless alpha reaches a hash of the ray and the hit.
// This is pbrt-v4's stochastic alpha test (GeometricPrimitive::Intersect: u = HashFloat(r.o,
// r.d), the hit is ignored when u > alpha, and alpha <= 0 always ignores it). pbrt-v4 spawns a
// new ray past a rejected hit, so its next test hashes a new origin; Embree keeps the ray, so
// the hash here also takes the hit (instance, geometry, primitive and distance) to keep two
// cut-out surfaces along one ray independent. The hash depends on nothing but the ray and the
// hit: images do not depend on threads or on the order Embree visits primitives in.
#pragma once

#include <embree3/rtcore.h>

#include <bit>
#include <cstdint>

#include "lamina/core/hash.h"
#include "lamina/core/vector.h"
#include "lamina/scene/scene_description.h"
#include "lamina/scene/texture.h"

namespace lamina::render {

/// What a cut-out shape's filter needs: the constant or texture, and the mesh for the uv.
struct AlphaTest {
    float value = 1;
    const Texture* texture = nullptr;
    const MeshDesc* mesh = nullptr;  ///< the shape (a texture alpha is read at its uv)
};

/// A number in [0, 1) from the ray (origin, direction) and the hit (the ids and distance).
inline float alphaHash(const Vec3<float>& origin, const Vec3<float>& direction, std::uint32_t inst,
                       std::uint32_t geom, std::uint32_t prim, float t) {
    const auto bits = [](float x) { return std::uint64_t(std::bit_cast<std::uint32_t>(x)); };
    const std::uint64_t h = hashValues(
        {bits(origin.x) | bits(origin.y) << 32u, bits(origin.z) | bits(direction.x) << 32u,
         bits(direction.y) | bits(direction.z) << 32u,
         std::uint64_t(inst) | std::uint64_t(geom) << 32u, std::uint64_t(prim) | bits(t) << 32u});
    return float(h >> 40u) * 0x1p-24f;  // 24 bits: exactly representable, below 1
}

/// The alpha of a cut-out shape at barycentrics (u, v) of triangle `prim`, at the point `p`
/// (in the space the ray was traced in: the world, or an instance's object; read by the
/// textures that project the point).
float alphaAt(const AlphaTest& test, std::uint32_t prim, float u, float v,
              const Vec3<float>& p = Vec3<float>(0.0f));

/// The Embree filter (intersection and occlusion alike) of a cut-out shape; its user data is
/// the shape's AlphaTest.
void alphaFilter(const RTCFilterFunctionNArguments* args);

}  // namespace lamina::render
