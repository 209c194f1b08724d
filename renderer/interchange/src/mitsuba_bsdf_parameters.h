// The parameters several Mitsuba 3 BSDF plugins share: indices of refraction, microfacet
// roughness, the scale factors lamina refuses, one-sidedness (docs/interchange.md, "Mitsuba 3").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mitsuba_plugin.h"
#include "mitsuba_textures.h"

namespace lamina::render::mitsuba {

/// Mitsuba's named indices of refraction (mitsuba3 include/mitsuba/render/ior.h, Hecht's
/// Optics at ~589 nm); nullopt for an unknown name.
std::optional<double> namedIor(const std::string& name);

/// An index of refraction: a <float> or one of Mitsuba's names (mitsuba3 lookup_ior: the
/// property's type decides); `fallback` names the default.
double indexOfRefraction(Plugin& p, const char* name, const char* fallback);

/// The relative index of refraction int_ior / ext_ior.
double relativeIor(Plugin& p, const char* defaultInterior, const char* defaultExterior);

/// Microfacet roughness of the rough plugins: `alpha` (0.1) or `alpha_u` / `alpha_v` (numbers
/// or a texture), and `distribution` (`beckmann`, Mitsuba's default, or `ggx`). Written into
/// `m` as lamina's `distribution` and `alpha` (or `alpha_x`, `alpha_y`, or a textured
/// `roughness`); a texture's definitions into `textures`.
void microfacetRoughness(Plugin& p, Json& m, bool anisotropic,
                         std::vector<TranslatedTexture>& textures);

/// Refuses a scale parameter (`specular_reflectance`...) other than 1.
void refuseScale(Plugin& p, const char* name);

/// Warns that a one-sided Mitsuba BSDF (black seen from behind) became lamina's two-sided
/// material `became`, unless it is inside a `twosided`.
void warnOneSided(Plugin& p, bool insideTwoSided, const std::string& became);

}  // namespace lamina::render::mitsuba
