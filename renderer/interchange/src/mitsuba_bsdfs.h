// Mitsuba 3 BSDF plugins -> lamina materials (docs/interchange.md, "Mitsuba 3").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mitsuba_plugin.h"
#include "mitsuba_textures.h"

namespace lamina::render::mitsuba {

/// A translated `<bsdf>`: the lamina material, for `mask` the shape's alpha (a number or
/// {"texture": name}), and the textures the material and the alpha name.
struct TranslatedBsdf {
    Json material;
    std::optional<Json> alpha;
    std::vector<TranslatedTexture> textures;
};

/// The world directions of a shape's surface parameterisation where they are the same over the
/// whole shape (a rectangle's dp/du and dp/dv, unit length): what Mitsuba's `polarizer` turns
/// its axis in.
struct SurfaceDirections {
    glm::dvec3 u, v;
};

/// Translates `bsdf` (and what it nests). `insideTwoSided`: the BSDF is wrapped in
/// `twosided`, so lamina's two-sided materials are exact. `depth`: how deep in other BSDFs
/// this one is (refs can make a cycle: nesting deeper than 16 is refused). `surface`: the
/// shape's parameterisation directions, when the BSDF is a shape's own and the shape has them.
TranslatedBsdf translateBsdf(const Element& bsdf, const MitsubaDocument& document,
                             Diagnostics& diagnostics, bool insideTwoSided = false, int depth = 0,
                             const SurfaceDirections* surface = nullptr);

/// `hair` (mitsuba_hair.cpp) -> lamina's `hair` material.
Json hairMaterial(Plugin& p);

}  // namespace lamina::render::mitsuba
