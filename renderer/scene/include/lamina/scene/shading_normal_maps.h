// Bump and normal maps: the shading normal a material's `displacement` (a height texture) or
// `normal_map` (a tangent-space image) makes at a surface point, from how the point moves with
// its uv. Materials name them (material_textures.h reads the keys); the geometry applies them
// to every hit (geometry.h), so every integrator shades with the same normal and light
// subpaths carry the adjoint correction of shading normals as they do for interpolated vertex
// normals (shading_normals.h).
#pragma once

#include "lamina/core/vector.h"
#include "lamina/scene/texture_mapping.h"

namespace lamina::render {

class Texture;
struct SceneDesc;

/// How a surface point moves and turns with its uv parameterisation: dp/du, dp/dv, and the
/// derivatives of its (unit) shading normal, dn/du and dn/dv (pbrt-v4's SurfaceInteraction
/// fields, the book's section 6.1). dp/du x dp/dv = 0 where the parameterisation degenerates
/// (a sphere's poles, a disk's centre, a triangle without distinct uvs).
struct SurfaceDerivatives {
    Vec3<float> dpdu{0.0f}, dpdv{0.0f};
    Vec3<float> dndu{0.0f}, dndv{0.0f};
};

/// The uv step of the finite differences of a height: pbrt-v4's when a ray carries no
/// differentials (BumpMap, materials.h).
inline constexpr float kBumpStep = 0.0005f;

/// Bump mapping (Blinn 1978; pbrt-v4 book section 10.5.1): the surface displaced along the
/// shading normal n by the height h (the texture's first channel, in scene units) has the
/// tangents dp'/du = t_u + dh/du n + h dn/du and dp'/dv = t_v + dh/dv n + h dn/dv, with t_u, t_v
/// dp/du, dp/dv in the plane normal to n (pbrt-v4's shading tangent; the same as dp/du where n
/// is the geometric normal), and the normal dp'/du x dp'/dv, on n's side of the
/// parameterisation. dh/du and dh/dv are central differences of step kBumpStep (pbrt-v4 takes
/// forward ones). Where the parameterisation degenerates, the tangents are the unit frame
/// around n (Frame::fromNormal). `ns`: unit. Returns a unit normal (`ns` if the bump leaves no
/// finite one). The height is looked up at `at` moved along t_u and t_v with its uv, so that
/// solid textures are differenced along the surface too.
Vec3<float> bumpMappedNormal(const Texture& height, const TexturePoint& at, const Vec3<float>& ns,
                             const SurfaceDerivatives& d);

/// Normal mapping (pbrt-v4's NormalMap, materials.h): the texel's colour c in [0, 1]^3 is the
/// direction 2c - 1 in the tangent frame x = dp/du made normal to n, z = n, y = z x x.
/// Returns a unit normal (`ns` if the texel's direction is zero).
Vec3<float> normalMappedNormal(const Texture& map, const TexturePoint& at, const Vec3<float>& ns,
                               const Vec3<float>& dpdu);

/// The shading normal of `material`'s bump or normal map at the point, turned into the
/// hemisphere of the geometric normal `ng` as every shading normal is (geometry.h); `ns` for a
/// material that has neither.
Vec3<float> perturbedShadingNormal(const SceneDesc& scene, int material, const TexturePoint& at,
                                   const Vec3<float>& ng, const Vec3<float>& ns,
                                   const SurfaceDerivatives& d);

}  // namespace lamina::render
