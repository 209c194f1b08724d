// Mitsuba 3's `principled` and `principledthin` BSDFs (Burley 2012 and 2015, as mitsuba3
// src/bsdfs/principled.cpp and principledthin.cpp evaluate them) -> lamina materials
// (docs/interchange.md, "Mitsuba 3").
#pragma once

#include <vector>

#include "mitsuba_plugin.h"
#include "mitsuba_textures.h"

namespace lamina::render::mitsuba {

/// A translated principled BSDF: the lamina material, and whether Mitsuba's is black seen
/// from behind (the caller warns when it is not inside a `twosided`).
struct TranslatedPrincipled {
    Json material;
    bool oneSided = false;
};

/// `principled`: lamina's `standard` with Burley's diffuse, GGX with the separable Smith G and
/// Mitsuba's Fresnel where lamina has it; a textured parameter's textures are appended to
/// `textures`.
TranslatedPrincipled principled(Plugin& p, std::vector<TranslatedTexture>& textures);

/// `principledthin`: lamina's `burley`, with diffuse transmission as a `mix`.
TranslatedPrincipled principledThin(Plugin& p, std::vector<TranslatedTexture>& textures);

}  // namespace lamina::render::mitsuba
