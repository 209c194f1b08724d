// Mitsuba 3 textures -> lamina textures (docs/interchange.md, "Mitsuba 3"): `bitmap` becomes an
// `image` texture and `checkerboard` a `checkerboard`, each with its `to_uv` mapped onto the
// lamina texture's scale (and an image's offset); what they cannot express is refused.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mitsuba_plugin.h"

namespace lamina::render::mitsuba {

/// A lamina texture a translated BSDF names: its name in the document's `textures`, its
/// definition, and the image file it reads, which the caller writes as `file` relative to the
/// document.
struct TranslatedTexture {
    std::string name;
    Json texture;
    std::filesystem::path file;  ///< empty: a texture of other textures, or a pattern
};

/// How a BSDF evaluates a texture parameter (mitsuba3 include/mitsuba/render/texture.h).
enum class TextureUse {
    /// A colour (Texture::eval): diffuse reflectance, lamina's `reflectance`.
    Color,
    /// A microfacet alpha (Texture::eval_1), which lamina takes as its textured `roughness`,
    /// alpha = roughness^2: the texture's values become their square roots.
    Alpha,
    /// A number in [0, 1] taken as it is (Texture::eval_1): the principled BSDF's `roughness`,
    /// which lamina's textured roughness takes with the same alpha = roughness^2.
    Scalar,
    /// A mask's opacity (Texture::eval_1): a number in [0, 1] taken as it is, lamina's
    /// textured `alpha` (which reads a texture's first channel).
    Opacity,
    /// The height of a bumpmap or the texels of a normalmap: a bitmap, its first channel or its
    /// colour as it is.
    Map,
};

/// `texture` (a `<texture>` element) as it is used for `use`, appended to `out` with the
/// textures it is made of; returns the name of the one the parameter names. `raw` receives a
/// bitmap's `raw` (false for a checkerboard).
std::string translateTexture(const Element& texture, TextureUse use,
                             const MitsubaDocument& document, Diagnostics& diagnostics,
                             std::vector<TranslatedTexture>& out, bool* raw = nullptr);

/// A colour parameter of `p` that may be a texture (nested, or a `<ref>` to one): a lamina
/// colour (Plugin::color), or {"texture": name} with the texture appended to `out`.
std::optional<Json> colorOrTexture(Plugin& p, const std::string& name,
                                   std::vector<TranslatedTexture>& out);

}  // namespace lamina::render::mitsuba
