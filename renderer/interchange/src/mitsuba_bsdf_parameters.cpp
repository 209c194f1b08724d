// The parameters several Mitsuba 3 BSDF plugins share (mitsuba_bsdf_parameters.h). Defaults
// are those of the plugin documentation in mitsuba3 src/bsdfs/*.cpp.
#include "mitsuba_bsdf_parameters.h"

#include <array>
#include <cctype>
#include <utility>

#include "lamina/core/error.h"

namespace lamina::render::mitsuba {

namespace {

constexpr std::array<std::pair<const char*, double>, 23> kNamedIors{{
    {"vacuum", 1.0},      {"helium", 1.000036},        {"hydrogen", 1.000132},
    {"air", 1.000277},    {"carbon dioxide", 1.00045}, {"water", 1.3330},
    {"acetone", 1.36},    {"ethanol", 1.361},          {"carbon tetrachloride", 1.461},
    {"glycerol", 1.4729}, {"benzene", 1.501},          {"silicone oil", 1.52045},
    {"bromine", 1.661},   {"water ice", 1.31},         {"fused quartz", 1.458},
    {"pyrex", 1.470},     {"acrylic glass", 1.49},     {"polypropylene", 1.49},
    {"bk7", 1.5046},      {"sodium chloride", 1.544},  {"amber", 1.55},
    {"pet", 1.5750},      {"diamond", 2.419},
}};

// A textured `alpha`, or `alpha_u` and `alpha_v` given by one texture, as lamina's textured
// roughness (sqrt(alpha), mitsuba_textures.h); false when alpha is not textured.
bool texturedAlpha(Plugin& p, Json& m, bool anisotropic, std::vector<TranslatedTexture>& textures) {
    const auto element = [&](const char* name) -> const Element* {
        const auto t = p.texture(name);
        return t ? t->texture : nullptr;
    };
    const Element* alpha = element("alpha");
    const Element* u = anisotropic ? element("alpha_u") : nullptr;
    const Element* v = anisotropic ? element("alpha_v") : nullptr;
    if (!alpha && !u && !v) return false;
    if ((u || v) && u != v)
        p.fail(
            "a textured alpha_u / alpha_v is supported only as one texture given to both "
            "(lamina's textured roughness is isotropic)");
    if (alpha && u) p.fail("give alpha or alpha_u / alpha_v, not both");
    const Element& texture = alpha ? *alpha : *u;
    m["roughness"] = {{"texture", translateTexture(texture, TextureUse::Alpha, p.document(),
                                                   p.diagnostics(), textures)}};
    return true;
}

}  // namespace

std::optional<double> namedIor(const std::string& name) {
    std::string lower;
    for (char c : name)
        lower += char(std::tolower(static_cast<unsigned char>(c)));
    for (const auto& [n, v] : kNamedIors)
        if (lower == n) return v;
    return std::nullopt;
}

// An index of refraction: a <float> or one of Mitsuba's names (mitsuba3 lookup_ior: the
// property's type decides).
double indexOfRefraction(Plugin& p, const char* name, const char* fallback) {
    if (p.tagOf(name) == "float" || p.tagOf(name) == "integer") {
        const double v = p.number(name, 1.0);
        if (!(v > 0)) p.fail(std::string("parameter \"") + name + "\" must be > 0");
        return v;
    }
    const std::string n = p.string(name).value_or(fallback);
    const auto v = namedIor(n);
    if (!v) p.fail(std::string("parameter \"") + name + "\": unknown material \"" + n + "\"");
    return *v;
}

// The index of refraction int_ior / ext_ior.
double relativeIor(Plugin& p, const char* defaultInterior, const char* defaultExterior) {
    const double interior = indexOfRefraction(p, "int_ior", defaultInterior);
    return interior / indexOfRefraction(p, "ext_ior", defaultExterior);
}

// Microfacet roughness of the rough plugins: `alpha` (0.1) or `alpha_u` / `alpha_v` (numbers
// or a texture), and `distribution` (`beckmann`, Mitsuba's default, or `ggx`). Written into
// `m`; a texture's definitions into `textures`.
void microfacetRoughness(Plugin& p, Json& m, bool anisotropic,
                         std::vector<TranslatedTexture>& textures) {
    const std::string distribution = p.string("distribution").value_or("beckmann");
    if (distribution != "beckmann" && distribution != "ggx")
        p.fail("distribution \"" + distribution + "\" is not supported (beckmann or ggx)");
    m["distribution"] = distribution;
    // Lamina samples visible normals always; Mitsuba's switch only changes the variance.
    if (p.has("sample_visible") && !p.boolean("sample_visible", true))
        p.warn("sample_visible false became lamina's visible-normal sampling (same expectation)");
    if (texturedAlpha(p, m, anisotropic, textures)) return;
    auto check = [&](double a, const char* name) {
        if (!(a >= 0 && a <= 1))
            p.fail(std::string("parameter \"") + name + "\" must be in [0, 1] for lamina");
        return a;
    };
    if (anisotropic && (p.has("alpha_u") || p.has("alpha_v"))) {
        if (p.has("alpha")) p.fail("give alpha or alpha_u / alpha_v, not both");
        m["alpha_x"] = check(p.number("alpha_u", 0.1), "alpha_u");
        m["alpha_y"] = check(p.number("alpha_v", 0.1), "alpha_v");
    } else {
        m["alpha"] = check(p.number("alpha", 0.1), "alpha");
    }
}

void refuseScale(Plugin& p, const char* name) {
    if (!p.has(name)) return;
    const auto c = p.color(name);
    if (c && *c != Json(1.0))
        p.fail(std::string("parameter \"") + name + "\" other than 1 is not supported");
}

void warnOneSided(Plugin& p, bool insideTwoSided, const std::string& became) {
    if (!insideTwoSided)
        p.warn("one-sided in Mitsuba (black seen from behind) became lamina's " + became +
               ", which reflects on both sides");
}

}  // namespace lamina::render::mitsuba
