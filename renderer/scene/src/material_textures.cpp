#include "lamina/scene/material_textures.h"
#include "lamina/core/json_reader.h"

#include <algorithm>

#include "lamina/bsdf/material_kind.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

namespace {

// An operand of a texture operation: the name of a texture, or a constant (a number or
// [r, g, b]; `colour` false: a number only).
std::shared_ptr<const Texture> readOperand(
    const JsonReader& t, const std::string& key, double fallback, bool colour, Range range,
    const TextureLookup& textureIndex,
    const std::vector<std::shared_ptr<const Texture>>& textures) {
    if (t.has(key) && t.value()[key].is_string())
        return textures[std::size_t(textureIndex(t, key, t.requiredString(key)))];
    if (colour) {
        const auto c = t.triple(key, {fallback, fallback, fallback}, range);
        return std::make_shared<ConstantTexture>(Rgb<float>(float(c[0]), float(c[1]), float(c[2])));
    }
    return std::make_shared<ConstantTexture>(Rgb<float>(float(t.number(key, fallback, range))));
}

// Why `key` of a material of type `kind` cannot name a texture, and what can.
std::string texturableKeysMessage(const MaterialKind& kind, const std::string& key) {
    std::string own;
    for (const TexturableKey& t : kind.texturable)
        own += (own.empty() ? "" : ", ") + std::string(t.key);
    std::string all;
    for (const MaterialKind* k : materialKinds()) {
        if (k->texturable.empty()) continue;
        std::string keys;
        for (const TexturableKey& t : k->texturable)
            keys += (keys.empty() ? "" : " / ") + std::string(t.key);
        all += (all.empty() ? "" : ", ") + std::string(k->name) + " (" + keys + ")";
    }
    return "a " + std::string(kind.name) + " material cannot take \"" + key + "\" from a texture" +
           (own.empty() ? "" : " (it can: " + own + ")") + "; textured parameters: " + all;
}

// Replaces the texture named by `key` of `r` (a key of a material of type `kind`) in `copy` by
// a constant the material parser accepts, and records which parameter it sets in `tex`.
void patchTexturedKey(const JsonReader& r, const MaterialKind& kind, const std::string& key,
                      Json& copy, MaterialTextures& tex, const TextureLookup& textureIndex) {
    const auto parameter = kind.texturedParameter(key);
    if (!parameter) r.failAt(key, texturableKeysMessage(kind, key));
    const JsonReader t(r.value()[key], r.childPath(key), r.source());
    const std::string name = t.requiredString("texture");
    t.finish();
    (*parameter == TexturedParameter::Roughness ? tex.roughness : tex.color) =
        textureIndex(t, "texture", name);
    copy[key] = 0.5;
}

// The textures of a material nested in another (coated's base: MaterialKind::texturedThrough),
// patched in `copy` as patchTexturedKey does. The shading-normal maps belong to the outer
// material (docs/scene-format.md). Returns whether the nested material's roughness is textured.
bool patchNestedTextures(const JsonReader& r, Json& copy, MaterialTextures& tex,
                         const TextureLookup& textureIndex) {
    const Json& type = r.value().value("type", Json());
    const MaterialKind* kind =
        type.is_string() ? findMaterialKind(type.get<std::string>()) : nullptr;
    if (!kind) return false;  // the parser names what is wrong with the type
    for (const char* map : {"displacement", "normal_map"})
        if (r.value().contains(map))
            r.failAt(map,
                     "a nested material takes no bump or normal map: give it to the "
                     "outer material");
    const int roughnessBefore = tex.roughness;
    for (const auto& [key, value] : r.value().items())
        if (value.is_object() && value.contains("texture"))
            patchTexturedKey(r, *kind, key, copy, tex, textureIndex);
    return tex.roughness != roughnessBefore;
}

}  // namespace

std::shared_ptr<const Texture> readTexture(
    const JsonReader& t, const TextureLookup& textureIndex,
    const std::vector<std::shared_ptr<const Texture>>& textures) {
    t.expectObject();
    t.noteNames("type", kTextureKindNames.names());
    const std::string type = t.requiredString("type");
    const auto kind = kTextureKindNames.find(type);
    if (!kind)
        t.failAt("type", "expected " + kTextureKindNames.list(" or ") + ", got \"" + type + "\"");
    Vec2<float> scale(1.0f);
    // [u, v] repeats of the patterns (has() marks the key as known: ask only where it is).
    const bool pattern = *kind == TextureKind::Checkerboard || *kind == TextureKind::Image;
    if (pattern && t.has("scale")) {
        const auto sc = t.requiredArray<2>("scale", Range::positive());
        scale = Vec2<float>(float(sc[0]), float(sc[1]));
    }
    std::shared_ptr<const Texture> texture;
    switch (*kind) {
        case TextureKind::Checkerboard: {
            const auto a = t.triple("a", {0.8, 0.8, 0.8}, Range::nonNegative());
            const auto b = t.triple("b", {0.2, 0.2, 0.2}, Range::nonNegative());
            if (!t.has("scale")) scale = Vec2<float>(8.0f);
            texture = std::make_shared<CheckerboardTexture>(
                Rgb<float>(float(a[0]), float(a[1]), float(a[2])),
                Rgb<float>(float(b[0]), float(b[1]), float(b[2])), scale);
            break;
        }
        case TextureKind::Image: {
            const std::filesystem::path file = t.filePath("file");
            const bool srgb = t.choice("color_space", TextureColorSpace::Srgb,
                                       kTextureColorSpaceNames) == TextureColorSpace::Srgb;
            const bool invert = t.boolean("invert", false);
            Vec2<float> offset(0.0f);
            if (t.has("offset")) {
                const auto o = t.requiredArray<2>("offset", {-1e6, 1e6});
                offset = Vec2<float>(float(o[0]), float(o[1]));
            }
            try {
                texture = std::make_shared<ImageTexture>(file, scale, srgb, invert, offset);
            } catch (const InputError& e) {
                t.failAt("file", e.what());
            }
            break;
        }
        case TextureKind::Scale:
        case TextureKind::Power: {
            if (!t.has("texture") || !t.value()["texture"].is_string())
                t.failAt("texture", "expected the name of a texture");
            const auto source =
                textures[std::size_t(textureIndex(t, "texture", t.requiredString("texture")))];
            if (*kind == TextureKind::Scale)
                texture = std::make_shared<ScaleTexture>(
                    source, float(t.requiredNumber("scale", {0.0, 1e6})));
            else
                texture = std::make_shared<PowerTexture>(
                    source, float(t.requiredNumber("exponent", {0.0625, 16.0})));
            break;
        }
        case TextureKind::Mix: {
            // pbrt-v4's defaults: tex1 0, tex2 1, amount 0.5.
            auto a = readOperand(t, "a", 0.0, true, Range::nonNegative(), textureIndex, textures);
            auto b = readOperand(t, "b", 1.0, true, Range::nonNegative(), textureIndex, textures);
            auto amount =
                readOperand(t, "amount", 0.5, false, Range::unit(), textureIndex, textures);
            texture = std::make_shared<MixTexture>(std::move(a), std::move(b), std::move(amount));
            break;
        }
    }
    t.finish();
    return texture;
}

// Replaces {"texture": name} in the keys the material's type may texture (its registration,
// material_kind.h) by a constant the material parser accepts, then checks that the material
// can take the textures it names. Any other object ({"spectrum": [[nm, value], ...]}, a
// measured reflectance) is the material parser's.
std::pair<MaterialDesc, MaterialTextures> readTexturedMaterial(const JsonReader& r,
                                                               const TextureLookup& textureIndex) {
    if (!r.value().is_object()) return {parseMaterial(r), {}};
    const Json& type = r.value().value("type", Json());
    const MaterialKind* kind =
        type.is_string() ? findMaterialKind(type.get<std::string>()) : nullptr;
    if (!kind) return {parseMaterial(r), {}};  // the parser names what is wrong with the type
    Json copy = r.value();
    MaterialTextures tex;
    // The shading-normal maps belong to the scene's material, not to its BSDF: read here and
    // taken out of what the material parser reads.
    for (const auto& [key, index] :
         {std::pair{"displacement", &tex.displacement}, std::pair{"normal_map", &tex.normalMap}}) {
        if (!r.has(key)) continue;
        const JsonReader t = r.child(key);
        if (!t.value().is_object() || !t.value().contains("texture"))
            t.fail("expected {\"texture\": name}");
        const std::string name = t.requiredString("texture");
        t.finish();
        *index = textureIndex(t, "texture", name);
        copy.erase(key);
    }
    if (tex.displacement >= 0 && tex.normalMap >= 0)
        r.failAt("normal_map",
                 "a material takes a displacement (a bump map) or a normal_map, not both");
    bool nestedRoughness = false;
    for (const auto& [key, value] : r.value().items()) {
        if (!copy.contains(key)) continue;  // a shading-normal map, read above
        if (!kind->texturedThrough.empty() && key == kind->texturedThrough && value.is_object()) {
            nestedRoughness = patchNestedTextures(r.child(key), copy[key], tex, textureIndex);
            continue;
        }
        if (!value.is_object() || !value.contains("texture")) continue;
        patchTexturedKey(r, *kind, key, copy, tex, textureIndex);
    }
    if (nestedRoughness)
        r.failAt(std::string(kind->texturedThrough),
                 "a textured roughness inside a " + std::string(kind->name) +
                     " material is not supported (its colour may be textured)");
    const JsonReader patched(copy, r.path(), r.source());
    MaterialDesc desc = parseMaterial(patched);
    if (tex.roughness >= 0) {
        if (kind->tabulatesRoughness && kind->tabulatesRoughness(desc.model))
            r.failAt("roughness",
                     "a textured roughness cannot use the albedo tables of "
                     "multiscatter or the albedo coupling");
        if (copy.contains("anisotropy")) r.failAt("roughness", "a textured roughness is isotropic");
    }
    return {std::move(desc), tex};
}

MaterialDesc texturedMaterial(const SceneDesc& scene, int material, const Vec2<float>& uv) {
    MaterialDesc desc = scene.materials[std::size_t(material)];
    const MaterialTextures& t = scene.materialTextures[std::size_t(material)];
    TexturedValues values;
    if (t.color >= 0) {
        const Rgb<float> c = scene.textures[std::size_t(t.color)]->evaluate(uv);
        values.color =
            RgbInput(std::clamp(double(c[0]), 0.0, 1.0), std::clamp(double(c[1]), 0.0, 1.0),
                     std::clamp(double(c[2]), 0.0, 1.0));
    }
    if (t.roughness >= 0)
        values.roughness =
            std::clamp(double(scene.textures[std::size_t(t.roughness)]->evaluate(uv)[0]), 0.0, 1.0);
    // Only a type with texturable keys, or a material nested through texturedThrough, has
    // textures (readTexturedMaterial).
    findMaterialKind(desc.type)->applyTextures(desc.model, values);
    return desc;
}

}  // namespace lamina::render
