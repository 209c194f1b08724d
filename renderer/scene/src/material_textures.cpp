#include "lamina/scene/material_textures.h"
#include "lamina/core/json_reader.h"

#include <algorithm>

#include "lamina/bsdf/material_kind.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

namespace {

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

MaterialDesc texturedMaterial(const SceneDesc& scene, int material, const TexturePoint& at) {
    MaterialDesc desc = scene.materials[std::size_t(material)];
    const MaterialTextures& t = scene.materialTextures[std::size_t(material)];
    TexturedValues values;
    if (t.color >= 0) {
        const Rgb<float> c = scene.textures[std::size_t(t.color)]->evaluate(at);
        values.color =
            RgbInput(std::clamp(double(c[0]), 0.0, 1.0), std::clamp(double(c[1]), 0.0, 1.0),
                     std::clamp(double(c[2]), 0.0, 1.0));
    }
    if (t.roughness >= 0)
        values.roughness =
            std::clamp(double(scene.textures[std::size_t(t.roughness)]->evaluate(at)[0]), 0.0, 1.0);
    // Only a type with texturable keys, or a material nested through texturedThrough, has
    // textures (readTexturedMaterial).
    findMaterialKind(desc.type)->applyTextures(desc.model, values);
    return desc;
}

}  // namespace lamina::render
