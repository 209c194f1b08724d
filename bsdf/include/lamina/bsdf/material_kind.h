// One registration per material type: everything the rest of lamina needs to know about a kind
// of material, kept in the reader file of that type (bsdf/src/*_reader.cpp): its name (the JSON
// "type"), its reader, its branch of the scene schema, the parameters a scene may take from a
// texture and how a texture's value sets them, the spectral data `lamina info` reports and the
// materials nested in it. The scene reader, the textures, `lamina info`, the schema test and the
// Python module take what they need from materialKinds(), never from a type's name.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lamina/bsdf/material.h"
#include "lamina/core/frame.h"

namespace lamina {

/// What a textured parameter of a material is.
enum class TexturedParameter {
    Color,     ///< a reflectance colour: the texture's RGB, each channel clamped to [0, 1]
    Roughness  ///< a perceptual roughness: the texture's first channel, clamped to [0, 1]
};
inline constexpr NameTable kTexturedParameterNames{
    std::array{NameEntry{TexturedParameter::Color, "color"},
               NameEntry{TexturedParameter::Roughness, "roughness"}}};

/// A key of a material's JSON object that may name a texture ({"texture": name}).
struct TexturableKey {
    std::string_view key;
    TexturedParameter parameter;
};

/// The textured parameters' values where a ray hit the surface (those the material has).
struct TexturedValues {
    std::optional<RgbInput> color;
    std::optional<double> roughness;
};

struct MaterialKind {
    std::string_view name;  ///< the JSON "type"
    /// Where messages, `lamina info` and the scene schema list this type among the others
    /// (ascending; the built-in types are 10, 20, ...).
    int listPosition;
    /// Reads the keys of one material object of this type (validated; InputError otherwise).
    MaterialModel (*read)(const JsonReader&);
    /// This type's branch of $defs.material in docs/scene.schema.json (JSON text); the schema
    /// test holds the file to it and scripts/update-material-schema.py writes it there.
    std::string_view schema;
    /// The keys a scene may texture; empty: none.
    std::span<const TexturableKey> texturable = {};
    /// Sets the textured parameters of a model this type read (null when `texturable` is
    /// empty).
    void (*applyTextures)(MaterialModel&, const TexturedValues&) = nullptr;
    /// Appends what `lamina info` names as the spectral data of a model of this type ("gold
    /// (n, k)"); null: none.
    void (*spectralData)(const MaterialModel&, std::vector<std::string>&) = nullptr;
    /// The materials inside a model of this type (mix: a and b; coated: its base); null: none.
    std::vector<const MaterialDesc*> (*nested)(const MaterialModel&) = nullptr;
    /// Turns the world directions of a model of this type into the shading frame `frame` of a
    /// hit (the axes of the polariser and retarder, which only the polarised mode sees); null:
    /// the type has none.
    void (*orient)(MaterialModel&, const Frame<double>& frame) = nullptr;
    /// What the polarised mode makes of this type, as `lamina info` says it
    /// (docs/polarisation.md, "What each material does").
    std::string_view polarisation = "an ideal depolariser";
    /// The key of a material nested in this type whose texturable keys a scene may texture
    /// (coated: "base", pbrt-v4's coateddiffuse with a textured reflectance); its textures set
    /// the nested material's parameters, through this type's applyTextures. Empty: none.
    std::string_view texturedThrough = {};
    /// Whether a model of this type lets light through the surface (coated refuses such a
    /// base: its walk has no way below it); null: never.
    bool (*transmits)(const MaterialModel&) = nullptr;
    /// Whether a model of this type holds tables computed from its roughness when it was read
    /// (multiscatter's albedo table, the albedo coupling), which a textured roughness could not
    /// follow from hit to hit; null: never.
    bool (*tabulatesRoughness)(const MaterialModel&) = nullptr;

    /// The parameter `key` takes from a texture, if it may be textured.
    std::optional<TexturedParameter> texturedParameter(std::string_view key) const;
};

/// Every material type, in the order messages and the schema list them (listPosition).
std::span<const MaterialKind* const> materialKinds();
/// The type called `name`; nullptr if there is none.
const MaterialKind* findMaterialKind(std::string_view name);
/// Whether `m` has world directions to turn into each hit's shading frame (orient).
bool needsOrientation(const MaterialDesc& m);
/// `m` with its world directions turned into the shading frame `frame` (a copy; `m` itself
/// if it has none).
MaterialDesc orientedMaterial(const MaterialDesc& m, const Frame<double>& frame);
/// Whether `m` lets light through the surface (MaterialKind::transmits).
bool materialTransmits(const MaterialDesc& m);
/// The spectral data of `m` and of every material nested in it, for `lamina info`.
void collectSpectralData(const MaterialDesc& m, std::vector<std::string>& out);

}  // namespace lamina
