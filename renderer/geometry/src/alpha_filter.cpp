#include "lamina/geometry/alpha_filter.h"

namespace lamina::render {

float alphaAt(const AlphaTest& test, std::uint32_t prim, float u, float v, const Vec3<float>& p) {
    if (!test.texture) return test.value;
    // The uv as Geometry::intersect computes it: the mesh's, else the barycentrics.
    Vec2<float> uv(u, v);
    if (test.mesh && !test.mesh->uvs.empty()) {
        const auto& tri = test.mesh->triangles[prim];
        const auto& uvs = test.mesh->uvs;
        uv = (1.0f - u - v) * uvs[tri[0]] + u * uvs[tri[1]] + v * uvs[tri[2]];
    }
    return test.texture->evaluate(TexturePoint(uv, p))[0];
}

void alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto& test = *static_cast<const AlphaTest*>(args->geometryUserPtr);
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        const std::uint32_t prim = RTCHitN_primID(args->hit, n, i);
        const Vec3<float> o(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i),
                            RTCRayN_org_z(args->ray, n, i));
        const Vec3<float> d(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i),
                            RTCRayN_dir_z(args->ray, n, i));
        const float alpha =
            alphaAt(test, prim, RTCHitN_u(args->hit, n, i), RTCHitN_v(args->hit, n, i),
                    o + RTCRayN_tfar(args->ray, n, i) * d);
        if (alpha >= 1.0f) continue;
        const float u = alpha <= 0.0f ? 1.0f
                                      : alphaHash(o, d, RTCHitN_instID(args->hit, n, i, 0),
                                                  RTCHitN_geomID(args->hit, n, i), prim,
                                                  RTCRayN_tfar(args->ray, n, i));
        if (u > alpha) args->valid[i] = 0;
    }
}

}  // namespace lamina::render
