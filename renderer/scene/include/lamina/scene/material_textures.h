// Textures in materials: reading a scene file's texture definitions and the material keys
// that name a texture ({"texture": name} for base_color / reflectance / roughness, and the
// shading-normal maps `displacement` and `normal_map` of any material), and the material with
// its textured parameters looked up at a surface's uv.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "lamina/bsdf/material.h"
#include "lamina/scene/texture.h"

namespace lamina::render {

struct SceneDesc;

/// Which parameters of a material come from textures (indices into SceneDesc::textures).
struct MaterialTextures {
    int color = -1;      ///< base_color (standard) or reflectance (diffuse, phong; a coat's base's)
    int roughness = -1;  ///< perceptual roughness, from the texture's first channel
    /// The shading-normal maps (shading_normal_maps.h), at most one of the two: a height in
    /// scene units (the texture's first channel), or a tangent-space normal map.
    int displacement = -1;
    int normalMap = -1;
    /// A parameter of the BSDF comes from a texture: the BSDF is built at every hit.
    bool any() const { return color >= 0 || roughness >= 0; }
    /// The material turns the shading normal: the geometry applies it at every hit.
    bool perturbsNormal() const { return displacement >= 0 || normalMap >= 0; }
};

/// Finds a texture by name for the key of `at` that names it (failing there when unknown, or
/// when the name refers back to a texture being read), loading it on first use; returns its
/// index into SceneDesc::textures.
using TextureLookup =
    std::function<int(const JsonReader& at, const std::string& key, const std::string& name)>;

/// A texture definition (texture_reader.cpp; docs/scene-format.md, "textures"): {"type":
/// "checkerboard", "a": colour, "b": colour, "scale": [u, v]}, {"type": "image", "file": path,
/// "scale": [u, v], "color_space": "srgb" | "linear", "invert": bool}, {"type": "scale",
/// "texture": name, "scale": number}, {"type": "mix", "a": name | colour, "b": name | colour,
/// "amount": name | number}, the noise textures fbm, wrinkled, windy, marble and dots
/// (procedural_textures.h), and the 2D textures' and solid textures' "mapping"
/// (texture_mapping.h). `textures` are the scene's textures so far, which `textureIndex`
/// indexes.
std::shared_ptr<const Texture> readTexture(
    const JsonReader& t, const TextureLookup& textureIndex,
    const std::vector<std::shared_ptr<const Texture>>& textures);

/// A material whose texturable keys may name a texture: the material (read with a constant
/// in their place) and which of its parameters the textures replace.
std::pair<MaterialDesc, MaterialTextures> readTexturedMaterial(const JsonReader& r,
                                                               const TextureLookup& textureIndex);

/// The material with its textured parameters looked up at `at`.
MaterialDesc texturedMaterial(const SceneDesc& scene, int material, const TexturePoint& at);

}  // namespace lamina::render
