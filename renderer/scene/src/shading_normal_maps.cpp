#include "lamina/scene/shading_normal_maps.h"

#include <cmath>

#include "lamina/core/frame.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

namespace {

bool finite(const Vec3<float>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// v without its component along the unit n.
Vec3<float> tangential(const Vec3<float>& v, const Vec3<float>& n) {
    return v - glm::dot(v, n) * n;
}

}  // namespace

Vec3<float> bumpMappedNormal(const Texture& height, const TexturePoint& at, const Vec3<float>& ns,
                             const SurfaceDerivatives& d) {
    Vec3<float> tu = tangential(d.dpdu, ns), tv = tangential(d.dpdv, ns);
    Vec3<float> side = glm::cross(tu, tv);
    if (!finite(side) || glm::dot(side, side) == 0.0f) {
        const Frame<float> frame = Frame<float>::fromNormal(ns);
        tu = frame.s;
        tv = frame.t;
        side = ns;
    }
    // The point moves with uv along the tangents (pbrt-v4's BumpMap shifts p by du dp/du), so
    // a solid texture's height is differenced along the surface as a uv-mapped one is.
    const auto h = [&](float du, float dv) {
        return height.evaluate(TexturePoint(Vec2<float>(at.uv.x + du, at.uv.y + dv),
                                            at.p + du * tu + dv * tv, at.n))[0];
    };
    const float hu = (h(kBumpStep, 0) - h(-kBumpStep, 0)) / (2 * kBumpStep);
    const float hv = (h(0, kBumpStep) - h(0, -kBumpStep)) / (2 * kBumpStep);
    const float h0 = h(0, 0);
    const Vec3<float> dpdu = tu + hu * ns + h0 * d.dndu;
    const Vec3<float> dpdv = tv + hv * ns + h0 * d.dndv;
    const Vec3<float> n = safeNormalize(glm::cross(dpdu, dpdv));
    if (!finite(n) || n == Vec3<float>(0.0f)) return ns;
    // The cross product's side follows the parameterisation's: keep the one ns has.
    return glm::dot(side, ns) < 0 ? -n : n;
}

Vec3<float> normalMappedNormal(const Texture& map, const TexturePoint& at, const Vec3<float>& ns,
                               const Vec3<float>& dpdu) {
    const Rgb<float> c = map.evaluate(at);
    const Vec3<float> local = safeNormalize(Vec3<float>(2 * c[0] - 1, 2 * c[1] - 1, 2 * c[2] - 1));
    if (!finite(local) || local == Vec3<float>(0.0f)) return ns;
    const Frame<float> frame = Frame<float>::fromNormalTangent(ns, dpdu);
    return safeNormalize(frame.toWorld(local));
}

Vec3<float> perturbedShadingNormal(const SceneDesc& scene, int material, const TexturePoint& at,
                                   const Vec3<float>& ng, const Vec3<float>& ns,
                                   const SurfaceDerivatives& d) {
    const MaterialTextures& t = scene.materialTextures[std::size_t(material)];
    Vec3<float> n = ns;
    if (t.displacement >= 0)
        n = bumpMappedNormal(*scene.textures[std::size_t(t.displacement)], at, ns, d);
    else if (t.normalMap >= 0)
        n = normalMappedNormal(*scene.textures[std::size_t(t.normalMap)], at, ns, d.dpdu);
    return glm::dot(n, ng) < 0 ? -n : n;
}

}  // namespace lamina::render
