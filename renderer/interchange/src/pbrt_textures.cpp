// pbrt-v4 textures -> lamina textures (pbrt-v4 textures.cpp gives the parameters and their
// defaults). Each is translated when a material first uses it.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "lamina/core/error.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

// An operand of a texture operation (pbrt-v4's tex1, tex2, tex, scale, amount, value): the name
// of the lamina texture a "texture" parameter names, or the constant a number or an rgb gives
// (a number for a float operand); `fallback` when absent.
Json operand(TranslationContext& ctx, const Entity& e, const std::string& key,
             const std::string& valueType, double fallback) {
    const ParamList& params = e.params;
    const Param* p = params.find(key);
    if (!p) return fallback;
    if (canonicalParamType(p->type) == "texture") {
        if (p->strings.size() != 1) params.fail(*p, "expected one texture name");
        // A float `constant` texture is its value (a scale's factor stays a number).
        for (const TextureDef& t : ctx.scene.textures)
            if (valueType == "float" && t.name == p->strings[0] && t.valueType == "float" &&
                t.entity.type == "constant") {
                const double v = constantNumber(t.entity.params, "value", 1.0);
                t.entity.params.refuseUnused();
                return v;
            }
        return useTexture(ctx, p->strings[0], valueType, p->location);
    }
    if (valueType == "float") return params.number(key, fallback);
    Json c = colour(ctx, e, key, fallback, false);
    if (c.is_object())
        params.fail(*p, "a spectrum is not supported as a texture's operand (give rgb)");
    return c;
}

// A constant operand (a number or [r, g, b]) times `scale`.
Json scaledConstant(TranslationContext& ctx, const Entity& e, Json v, double scale) {
    if (scale < 0) ctx.fail(e.location, "texture \"scale\": a negative scale is not supported");
    if (v.is_number()) return v.get<double>() * scale;
    for (auto& x : v)
        x = x.get<double>() * scale;
    return v;
}

}  // namespace

std::string useTexture(TranslationContext& ctx, const std::string& name,
                       const std::string& valueType, const Location& usedAt) {
    const TextureDef* def = nullptr;
    for (const TextureDef& t : ctx.scene.textures)
        if (t.name == name && t.valueType == valueType) def = &t;
    if (!def) ctx.fail(usedAt, "no " + valueType + " texture named \"" + name + "\"");
    const std::string laminaName = valueType == "float" ? name + " (float)" : name;
    if (ctx.texturesInProgress.count(laminaName))
        ctx.fail(usedAt, "texture \"" + name + "\" is made of itself");
    if (ctx.writtenTextures.count(laminaName)) return laminaName;
    ctx.texturesInProgress.insert(laminaName);
    const Entity& e = def->entity;
    const ParamList& params = e.params;
    Json t;
    if (e.type == "imagemap") {
        const Param* file = params.find("filename");
        if (!file) ctx.fail(e.location, "imagemap: no \"string filename\" parameter");
        params.expectType(*file, {"string"});
        const std::string fileName = file->strings.at(0);
        // pbrt-v4 (textures.cpp): 8-bit PNGs default to sRGB, everything else to linear.
        const std::string extension = std::filesystem::path(fileName).extension().string();
        const bool png = extension == ".png" || extension == ".PNG";
        const std::string encoding = params.string("encoding", png ? "sRGB" : "linear");
        if (encoding != "sRGB" && encoding != "linear")
            ctx.fail(e.location,
                     "imagemap: encoding \"" + encoding + "\" is not supported (sRGB or linear)");
        t = {{"type", "image"},
             {"file", ctx.filePath(params, *file)},
             {"color_space", encoding == "sRGB" ? "srgb" : "linear"}};
        translateMapping2D(ctx, e, t);
        const std::string filter = params.string("filter", "bilinear");
        if (filter != "bilinear")
            ctx.warn(e.location,
                     "imagemap filter \"" + filter + "\" became lamina's bilinear lookup");
        if (params.has("maxanisotropy")) {
            params.number("maxanisotropy", 8);
            ctx.warn(e.location, "maxanisotropy ignored: lamina's lookups are bilinear");
        }
        if (params.string("wrap", "repeat") != "repeat")
            ctx.fail(e.location, "imagemap: only wrap \"repeat\" is supported");
        const bool invert = params.boolean("invert", false);
        const double scale = constantNumber(params, "scale", 1.0);
        if (invert) t["invert"] = true;
        if (scale != 1) {
            // pbrt-v4 scales first and inverts after (1 - scale v); lamina's image inverts
            // and the scale texture multiplies.
            if (invert)
                ctx.fail(e.location, "imagemap: scale together with invert is not supported");
            params.refuseUnused();
            const std::string imageName = laminaName + " (image)";
            ctx.document["textures"][imageName] = t;
            ctx.writtenTextures.insert(imageName);
            t = {{"type", "scale"}, {"texture", imageName}, {"scale", scale}};
        }
    } else if (e.type == "checkerboard") {
        const int dimension = params.integer("dimension", 2);
        if (dimension != 2 && dimension != 3)
            ctx.fail(e.location, "checkerboard: dimension must be 2 or 3");
        // pbrt-v4's Checkerboard (textures.cpp): tex1 where floor(u) + floor(v) (or the sum of
        // the point's three floors) is even, tex2 where it is odd; lamina's a and b.
        Json a = colour(ctx, e, "tex1", 1.0, false), b = colour(ctx, e, "tex2", 0.0, false);
        t = {{"type", "checkerboard"}, {"a", a}, {"b", b}};
        if (dimension == 3) {
            translateMapping3D(ctx, e, t);
            if (!t.contains("mapping")) t["mapping"] = {{"type", "point"}};
        } else {
            translateMapping2D(ctx, e, t);
        }
    } else if (e.type == "dots") {
        // pbrt-v4's DotsTexture: inside (1) in the dots, outside (0) between them, each a
        // texture or a constant.
        t = {{"type", "dots"},
             {"inside", operand(ctx, e, "inside", valueType, 1.0)},
             {"outside", operand(ctx, e, "outside", valueType, 0.0)}};
        translateMapping2D(ctx, e, t);
    } else if (auto solid = translateSolidTexture(ctx, e)) {
        t = std::move(*solid);
    } else if (e.type == "constant") {
        // pbrt-v4's constant textures (textures.cpp: "value", 1): the value everywhere, a
        // lamina mix of the value with itself at amount 0, exactly (1 - 0) v + 0 v = v.
        const Json v = operand(ctx, e, "value", valueType, 1.0);
        t = {{"type", "mix"}, {"a", v}, {"b", v}, {"amount", 0}};
    } else if (e.type == "scale") {
        // pbrt-v4's ScaleTexture (textures.h): tex times scale, each a texture or a constant.
        const Json tex = operand(ctx, e, "tex", valueType, 1.0);
        const Json scale = operand(ctx, e, "scale", "float", 1.0);
        if (scale.is_number() && tex.is_string()) {
            t = {{"type", "scale"}, {"texture", tex}, {"scale", scale}};
        } else if (scale.is_number()) {
            const Json v = scaledConstant(ctx, e, tex, scale.get<double>());
            t = {{"type", "mix"}, {"a", v}, {"b", v}, {"amount", 0}};
        } else {
            // A texture times a float texture s: lamina's mix of 0 and tex at amount s, which is
            // s tex where s is in [0, 1] (lamina clamps a mix's amount there).
            ctx.warn(e.location,
                     "texture \"scale\" by a texture became a mix of 0 and \"tex\" "
                     "at that amount: the scale's values are clamped to [0, 1]");
            t = {{"type", "mix"}, {"a", 0}, {"b", tex}, {"amount", scale}};
        }
    } else if (e.type == "mix") {
        // pbrt-v4's MixTexture (textures.h): tex1 (0) and tex2 (1), each a texture or a
        // constant, and amount (0.5), a float texture or a number: lamina's mix.
        t = {{"type", "mix"},
             {"a", operand(ctx, e, "tex1", valueType, 0.0)},
             {"b", operand(ctx, e, "tex2", valueType, 1.0)},
             {"amount", operand(ctx, e, "amount", "float", 0.5)}};
    } else if (e.type == "directionmix") {
        // pbrt-v4's DirectionMixTexture (textures.cpp): tex1 (0) where the geometric normal is
        // along dir, tex2 (1) where it is across, dir ((0, 1, 0)) turned by the transform in
        // effect at the Texture and normalised: lamina's direction_mix.
        glm::dvec3 dir(0, 1, 0);
        if (const auto v = params.numbers("dir", {"vector3"}, 3)) {
            if (v->size() != 3) params.fail(*params.find("dir"), "expected 3 numbers");
            dir = glm::dvec3((*v)[0], (*v)[1], (*v)[2]);
        }
        dir = glm::dmat3(e.transform) * dir;
        if (!(glm::length(dir) > 0) || !std::isfinite(glm::length(dir)))
            ctx.fail(e.location, "directionmix: \"dir\" is zero (after the transform)");
        dir = glm::normalize(dir);
        t = {{"type", "direction_mix"},
             {"a", operand(ctx, e, "tex1", valueType, 0.0)},
             {"b", operand(ctx, e, "tex2", valueType, 1.0)},
             {"direction", Json::array({dir.x, dir.y, dir.z})}};
    } else {
        ctx.fail(e.location, "texture \"" + e.type +
                                 "\" is not supported (lamina reads imagemap, constant, "
                                 "checkerboard, dots, fbm, wrinkled, windy, marble, scale, "
                                 "mix and directionmix)");
    }
    params.refuseUnused();
    ctx.document["textures"][laminaName] = t;
    ctx.texturesInProgress.erase(laminaName);
    ctx.writtenTextures.insert(laminaName);
    return laminaName;
}

}  // namespace lamina::render::pbrt
