// Mitsuba 3 BSDF plugins -> lamina materials (docs/interchange.md, "Mitsuba 3").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mitsuba_plugin.h"
#include "mitsuba_textures.h"

namespace lamina::render::mitsuba {

/// A translated `<bsdf>`: the lamina material, for `mask` the shape's alpha, and the textures
/// the material names.
struct TranslatedBsdf {
    Json material;
    std::optional<double> alpha;
    std::vector<TranslatedTexture> textures;
};

/// Translates `bsdf` (and what it nests). `insideTwoSided`: the BSDF is wrapped in
/// `twosided`, so lamina's two-sided materials are exact. `depth`: how deep in other BSDFs
/// this one is (refs can make a cycle: nesting deeper than 16 is refused).
TranslatedBsdf translateBsdf(const Element& bsdf, const MitsubaDocument& document,
                             Diagnostics& diagnostics, bool insideTwoSided = false, int depth = 0);

/// Mitsuba's named indices of refraction (mitsuba3 include/mitsuba/render/ior.h, Hecht's
/// Optics at ~589 nm); nullopt for an unknown name.
std::optional<double> namedIor(const std::string& name);

}  // namespace lamina::render::mitsuba
