#include <algorithm>

#include "lamina/scene/rgl_bsdf_file.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

void SceneMaterials::define(const JsonReader& materials) {
    materials.expectObject();
    for (const auto& [name, value] : materials.value().items()) {
        if (name == kInterfaceMaterialName)
            materials.failAt(name,
                             "\"interface\" names the index-matched boundary of media "
                             "(docs/media.md); choose another name");
        materials_.emplace_back(name, materials.child(name));
    }
    materials.finish();
}

void SceneMaterials::defineTextures(const JsonReader& textures) {
    textures.expectObject();
    for (const auto& [name, value] : textures.value().items())
        textures_.emplace_back(name, textures.child(name));
    textures.finish();
}

int SceneMaterials::materialOf(const JsonReader& shape) {
    if (!shape.has("material")) shape.failAt("material", "missing; every shape needs one");
    const JsonReader m = shape.child("material");
    if (m.value().is_string()) {
        const std::string name = m.value().get<std::string>();
        if (name == kInterfaceMaterialName) return kInterfaceMaterial;
        for (std::size_t i = 0; i < scene_.materialNames.size(); ++i)
            if (scene_.materialNames[i] == name) return int(i);
        for (const auto& [definedName, reader] : materials_)
            if (definedName == name) {
                const int index = add(reader);
                scene_.materialNames.push_back(name);
                return index;
            }
        std::string known;
        for (const auto& [n, reader] : materials_)
            known += (known.empty() ? "" : ", ") + n;
        m.fail("unknown material \"" + name + "\"" +
               (known.empty() ? " (the scene defines no materials)" : "; defined: " + known));
    }
    scene_.materialNames.push_back(m.path());
    return add(m);
}

int SceneMaterials::generated(const std::string& name, const Json& material,
                              const JsonSource& source,
                              const std::vector<std::pair<std::string, Json>>& textures) {
    // By name in a map: an OBJ may have as many groups as faces.
    if (const auto at = generated_.find(name); at != generated_.end()) return at->second;
    for (const auto& [textureName, texture] : textures) {
        scene_.textures.push_back(readTexture(
            JsonReader(texture, "", source),
            [this](const JsonReader& a, const std::string& k, const std::string& n) {
                return textureIndex(a, k, n);
            },
            scene_.textures));
        scene_.textureNames.push_back(textureName);
    }
    const int index = add(JsonReader(material, "", source));
    scene_.materialNames.push_back(name);
    generated_.emplace(name, index);
    return index;
}

void SceneMaterials::recordUnused() {
    const auto unused = [](const auto& defined, const std::vector<std::string>& used,
                           std::vector<std::string>& out) {
        for (const auto& [name, reader] : defined)
            if (std::find(used.begin(), used.end(), name) == used.end()) out.push_back(name);
    };
    unused(materials_, scene_.materialNames, scene_.unusedMaterialNames);
    unused(textures_, scene_.textureNames, scene_.unusedTextureNames);
}

int SceneMaterials::textureIndex(const JsonReader& at, const std::string& key,
                                 const std::string& name) {
    for (std::size_t i = 0; i < scene_.textureNames.size(); ++i)
        if (scene_.textureNames[i] == name) return int(i);
    // A texture operation names the textures it reads; one of them naming a texture still
    // being read would recurse for ever.
    if (std::find(reading_.begin(), reading_.end(), name) != reading_.end()) {
        std::string cycle;
        for (auto it = std::find(reading_.begin(), reading_.end(), name); it != reading_.end();
             ++it)
            cycle += *it + " -> ";
        at.failAt(key, "the textures refer to each other in a cycle: " + cycle + name);
    }
    for (const auto& [definedName, reader] : textures_)
        if (definedName == name) {
            reading_.push_back(name);
            auto texture = readTexture(
                reader,
                [this](const JsonReader& a, const std::string& k, const std::string& n) {
                    return textureIndex(a, k, n);
                },
                scene_.textures);
            reading_.pop_back();
            scene_.textures.push_back(std::move(texture));
            scene_.textureNames.push_back(name);
            return int(scene_.textures.size() - 1);
        }
    at.failAt(key, "unknown texture \"" + name + "\"");
}

int SceneMaterials::add(const JsonReader& material) {
    auto [desc, textures] = readTexturedMaterial(
        material, [this](const JsonReader& at, const std::string& key, const std::string& name) {
            return textureIndex(at, key, name);
        });
    // A normal map's texels are vectors: decoding them from sRGB would tilt every normal.
    if (textures.normalMap >= 0) {
        const auto* image = dynamic_cast<const ImageTexture*>(
            scene_.textures[std::size_t(textures.normalMap)].get());
        if (image && image->decodedSrgb())
            material.child("normal_map")
                .failAt("texture",
                        "a normal map's image must be read with \"color_space\": "
                        "\"linear\" (its texels are vectors, not sRGB colours)");
    }
    // The bsdf library reads no files: a measured material's table is read here.
    loadMeasuredTables(desc);
    scene_.materialTextures.push_back(textures);
    scene_.materials.push_back(std::move(desc));
    return int(scene_.materials.size() - 1);
}

}  // namespace lamina::render
