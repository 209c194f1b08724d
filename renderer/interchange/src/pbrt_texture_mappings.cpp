// pbrt-v4's texture mappings (textures.cpp, TextureMapping2D::Create and
// TextureMapping3D::Create) and its solid noise textures -> the lamina texture's keys
// (docs/scene-format.md, "Texture mappings"). A mapping that projects the point is placed by
// the transform in effect at the Texture directive, pbrt-v4's renderFromTexture.
#include <cmath>

#include "pbrt_shapes.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

// The texture's placement as a lamina transform, or null for the identity.
Json placement(const Entity& e) {
    if (e.transform == glm::dmat4(1.0)) return nullptr;
    if (!(std::abs(glm::determinant(e.transform)) > 1e-300))
        return nullptr;  // refused by the caller
    return Json::array({Json{{"matrix", rowMajor(e.transform)}}});
}

void requireInvertible(TranslationContext& ctx, const Entity& e) {
    if (!(std::abs(glm::determinant(e.transform)) > 1e-300))
        ctx.fail(e.location,
                 "the transform in effect at this Texture is singular: a projected or solid "
                 "texture needs an invertible one");
}

Json vector3(TranslationContext& ctx, const Entity& e, const std::string& name,
             const std::array<double, 3>& fallback) {
    const auto v = e.params.numbers(name, {"vector3"}, 3);
    if (!v) return Json::array({fallback[0], fallback[1], fallback[2]});
    if (v->size() != 3) ctx.fail(e.location, "\"vector3 " + name + "\": expected 3 numbers");
    return Json::array({(*v)[0], (*v)[1], (*v)[2]});
}

}  // namespace

void translateMapping2D(TranslationContext& ctx, const Entity& e, Json& t) {
    const ParamList& params = e.params;
    const std::string mapping = params.string("mapping", "uv");
    const double du = constantNumber(params, "udelta", 0.0);
    const double dv = constantNumber(params, "vdelta", 0.0);
    if (mapping == "uv") {
        // pbrt-v4's UVMapping: (uscale u + udelta, vscale v + vdelta); a negative scale
        // mirrors, as lamina's does.
        const double su = constantNumber(params, "uscale", 1.0);
        const double sv = constantNumber(params, "vscale", 1.0);
        if (su == 0 || sv == 0)
            ctx.fail(e.location, "a zero uscale / vscale maps the whole surface to one texel");
        t["scale"] = Json::array({su, sv});
        if (du != 0 || dv != 0) t["offset"] = Json::array({du, dv});
        return;
    }
    requireInvertible(ctx, e);
    Json m;
    if (mapping == "planar") {
        // pbrt-v4's PlanarMapping: (udelta + q . v1, vdelta + q . v2), q the point in the
        // texture's space; defaults v1 = x, v2 = y.
        m = {{"type", "planar"},
             {"v1", vector3(ctx, e, "v1", {1, 0, 0})},
             {"v2", vector3(ctx, e, "v2", {0, 1, 0})}};
        if (du != 0 || dv != 0) m["offset"] = Json::array({du, dv});
    } else if (mapping == "spherical" || mapping == "cylindrical") {
        m = {{"type", mapping}};
    } else {
        ctx.fail(e.location, "texture mapping \"" + mapping +
                                 "\" is not one of pbrt-v4's (uv, spherical, cylindrical, "
                                 "planar)");
    }
    if (Json p = placement(e); !p.is_null()) m["transform"] = std::move(p);
    t["mapping"] = std::move(m);
}

void translateMapping3D(TranslationContext& ctx, const Entity& e, Json& t) {
    requireInvertible(ctx, e);
    if (Json p = placement(e); !p.is_null())
        t["mapping"] = {{"type", "point"}, {"transform", std::move(p)}};
}

std::optional<Json> translateSolidTexture(TranslationContext& ctx, const Entity& e) {
    const bool noise = e.type == "fbm" || e.type == "wrinkled" || e.type == "windy";
    if (!noise && e.type != "marble") return std::nullopt;
    const ParamList& params = e.params;
    Json t = {{"type", e.type}};
    if (e.type != "windy") {
        // pbrt-v4's defaults: octaves 8, roughness (omega) 0.5; marble scale 1, variation 0.2.
        const int octaves = params.integer("octaves", 8);
        if (octaves < 1 || octaves > 30)
            ctx.fail(e.location,
                     e.type + ": octaves must be in [1, 30] (got " + std::to_string(octaves) + ")");
        const double roughness = constantNumber(params, "roughness", 0.5);
        if (!(roughness >= 0 && roughness <= 4))
            ctx.fail(e.location, e.type + ": roughness must be in [0, 4]");
        t["octaves"] = octaves;
        t["roughness"] = roughness;
        if (e.type == "marble") {
            t["scale"] = constantNumber(params, "scale", 1.0);
            t["variation"] = constantNumber(params, "variation", 0.2);
        }
    }
    translateMapping3D(ctx, e, t);
    ctx.warnOnce(e.location,
                 "noise textures (fbm, wrinkled, windy, marble) sum every octave at every point "
                 "in lamina, which has no pixel footprints; pbrt-v4 leaves out the octaves "
                 "finer than a pixel (the same pattern, more fine detail where it is small on "
                 "screen)");
    return t;
}

}  // namespace lamina::render::pbrt
