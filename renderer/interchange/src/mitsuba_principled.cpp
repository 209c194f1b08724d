// Mitsuba 3's principled BSDFs -> lamina materials (mitsuba_principled.h). What each parameter
// does is read from mitsuba3 src/bsdfs/principled.cpp, principledthin.cpp and
// principledhelpers.h; defaults are theirs.
//
// Burley 2015's split of the diffuse term, (1 - F_i / 2)(1 - F_o / 2) + R_R (F_i + F_o +
// F_i F_o (R_R - 1)) with F = (1 - cos)^5 and R_R = 2 roughness cos^2 theta_d, expands to
// Burley 2012's (1 + (F_D90 - 1) F_i)(1 + (F_D90 - 1) F_o) with F_D90 = 1/2 + R_R: lamina's
// `burley` diffuse model, retro-reflection included, is Mitsuba's term exactly.
#include "mitsuba_principled.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lamina/core/error.h"

namespace lamina::render::mitsuba {

namespace {

// A parameter lamina takes as one number: its value, which must be in [0, hi] (fallback when
// absent). A texture is refused on its own line.
double constantWeight(Plugin& p, const char* name, double fallback, double hi,
                      const std::string& why) {
    if (const auto t = p.texture(name))
        throw InputError(t->at->where() + ": " + p.element().describe() + ": a textured " + name +
                         " is not supported (" + why + ")");
    const double v = p.number(name, fallback);
    if (!(v >= 0 && v <= hi))
        p.fail(std::string("parameter \"") + name + "\" must be in [0, " + formatNumber(hi) + "]");
    return v;
}

constexpr const char* kStandardTextures =
    "lamina's standard material takes textures on base_color and roughness only; give a number";

// A parameter read for a lobe lamina does not have or that is switched off: whether it is
// given other than 0 (a texture counts as given).
bool givenNonZero(Plugin& p, const char* name) {
    if (p.texture(name)) return true;
    return p.number(name, 0.0) != 0;
}

// Sampling rates change only which lobe a sample picks, not what the BSDF is: read, with one
// warning naming those given.
void samplingRates(Plugin& p, std::initializer_list<const char*> names) {
    std::string given;
    for (const char* n : names) {
        if (!p.has(n)) continue;
        p.number(n, 1.0);
        given += (given.empty() ? "" : ", ") + std::string(n);
    }
    if (!given.empty())
        p.warn(given + " became lamina's own choice of lobes (the same expectation, other noise)");
}

// `roughness` (0.5): a number in [0, 1] or a texture of it. Both plugins take alpha =
// max(0.001, roughness^2) (principledhelpers.h calc_dist_params), lamina alpha = roughness^2
// with alpha below 0.001 a delta lobe (said when `specular`: the roughness of a specular lobe).
Json roughness(Plugin& p, std::vector<TranslatedTexture>& textures, bool specular) {
    if (const auto t = p.texture("roughness"))
        return Json{{"texture", translateTexture(*t->texture, TextureUse::Scalar, p.document(),
                                                 p.diagnostics(), textures)}};
    const double r = p.number("roughness", 0.5);
    if (!(r >= 0 && r <= 1)) p.fail("parameter \"roughness\" must be in [0, 1]");
    if (specular && r * r < 1e-3)
        p.warn("roughness " + formatNumber(r) +
               " became lamina's smooth (delta) reflection, where Mitsuba clamps alpha to 0.001");
    return r;
}

// principled.cpp: `eta`, or `specular` (0.5) as eta = 2 / (1 - sqrt(0.08 specular)) - 1, the
// index whose normal-incidence reflectance ((eta - 1) / (eta + 1))^2 is 0.08 specular (Burley
// 2012: specular 0.5 is F0 0.04). With a transmission lobe, eta 1 becomes 1.001 and specular 0
// becomes 0.001, as there.
double principledEta(Plugin& p, bool transmits) {
    if (p.has("eta") && p.has("specular")) p.fail("give eta or specular, not both");
    if (p.has("eta")) {
        const double eta = p.number("eta", 1.5);
        if (!(eta > 0 && eta <= 10)) p.fail("parameter \"eta\" must be in (0, 10]");
        return transmits && eta == 1 ? 1.001 : eta;
    }
    double specular = p.number("specular", 0.5);
    if (!(specular >= 0 && specular <= 1)) p.fail("parameter \"specular\" must be in [0, 1]");
    if (transmits && specular == 0) specular = 1e-3;
    return 2 / (1 - std::sqrt(0.08 * specular)) - 1;
}

// The lobes neither lamina material has: one warning each, the lobe dropped.
void dropUnsupportedLobes(Plugin& p) {
    const bool sheenTint = givenNonZero(p, "sheen_tint");
    if (givenNonZero(p, "sheen"))
        p.warn(std::string("sheen") + (sheenTint ? " and sheen_tint are" : " is") +
               " not supported: dropped (Mitsuba adds Burley's sheen lobe, sheen (1 - cos "
               "theta_d)^5, which lightens grazing angles)");
    if (givenNonZero(p, "flatness"))
        p.warn(
            "flatness is not supported: dropped (Mitsuba blends Burley's diffuse towards the "
            "Hanrahan-Krueger fake subsurface; lamina keeps Burley's diffuse, flatness 0)");
}

bool isWhite(const Json& c) {
    return c == Json(1.0) || c == Json::array({1.0, 1.0, 1.0});
}

// principled.cpp's clearcoat: an added GTR1 lobe, 0.25 clearcoat Schlick(0.04) D G, of alpha
// lerp(0.1, 0.001, clearcoat_gloss). Lamina has no added lobe: a mix of weight 0.25 clearcoat
// with the material under a clear coat of index 1.5 (F0 0.04) adds that share of a coat's
// reflection, and dims the base under it by what the coat reflects and absorbs.
Json clearcoat(Plugin& p, const Json& material, bool transmits) {
    const bool textured = p.texture("clearcoat").has_value();
    const double amount = textured ? 0.0 : constantWeight(p, "clearcoat", 0.0, 1.0, "");
    const bool glossTextured = p.texture("clearcoat_gloss").has_value();
    const double gloss = glossTextured ? 0.0 : p.number("clearcoat_gloss", 0.0);
    if (!(gloss >= 0 && gloss <= 1)) p.fail("parameter \"clearcoat_gloss\" must be in [0, 1]");
    if (!textured && amount == 0) return material;
    const bool materialTextured =
        material["base_color"].is_object() && material["base_color"].contains("texture");
    std::string why;
    if (textured || glossTextured) why = "with a textured clearcoat or clearcoat_gloss";
    if (materialTextured || material["roughness"].is_object()) why = "on a textured material";
    if (transmits) why = "with spec_trans (lamina's coat covers opaque bases only)";
    if (!why.empty()) {
        p.warn("clearcoat is not supported " + why +
               ": dropped (Mitsuba's clearcoat adds at most 0.25 of a clear coat's reflection)");
        return material;
    }
    // The smallest alpha lamina calls rough: a coat of alpha 0.001 stays a rough coat.
    const double alpha = std::max(0.001, 0.1 + (0.001 - 0.1) * gloss);
    p.warn(
        "clearcoat became a mix of weight 0.25 clearcoat with the material under a clear coat "
        "(index 1.5, GGX alpha " +
        formatNumber(alpha) +
        "): Mitsuba adds a GTR1 lobe (longer tails than GGX) on top of the whole material, "
        "where lamina's coat also dims the share of the base it covers");
    return Json{{"type", "mix"},
                {"a", material},
                {"b", {{"type", "coated"}, {"ior", 1.5}, {"alpha", alpha}, {"base", material}}},
                {"weight", 0.25 * amount}};
}

}  // namespace

TranslatedPrincipled principled(Plugin& p, std::vector<TranslatedTexture>& textures) {
    Json m{{"type", "standard"},
           {"diffuse_model", "burley"},
           {"coupling", "sum"},   // Mitsuba adds the diffuse term unweighted by the Fresnel
           {"g2", "separable"}};  // mitsuba3 microfacet.h G: G1(wi) G1(wo)
    m["base_color"] = colorOrTexture(p, "base_color", textures).value_or(Json(0.5));
    m["roughness"] = roughness(p, textures, true);
    const double metallic = constantWeight(p, "metallic", 0.0, 1.0, kStandardTextures);
    const double specTrans = constantWeight(p, "spec_trans", 0.0, 1.0, kStandardTextures);
    double anisotropic = constantWeight(p, "anisotropic", 0.0, 1.0, kStandardTextures);
    m["ior"] = principledEta(p, specTrans > 0);
    // Mitsuba: (1 - metallic)(1 - spec_tint) F_dielectric + metallic Schlick(base_color); lamina's
    // Schlick of lerp(F0, base_color, metalness) is the same blend of Schlick terms (Schlick's
    // formula is affine in F0), exact at metallic 1; at metallic 0 the exact Fresnel is Mitsuba's.
    m["fresnel"] = metallic > 0 ? "schlick" : "exact";
    if (metallic > 0) m["metalness"] = metallic;
    if (metallic > 0 && metallic < 1)
        p.warn(
            "metallic between 0 and 1: lamina's standard takes Schlick's Fresnel for the "
            "dielectric share too (F0 ((eta - 1) / (eta + 1))^2), where Mitsuba takes the exact "
            "dielectric Fresnel (the same at normal incidence, Schlick's error obliquely)");
    if (anisotropic > 0) {
        if (m["roughness"].is_object())
            p.fail(
                "a textured roughness with anisotropic is not supported (lamina's textured "
                "roughness is isotropic)");
        if (anisotropic > 0.99) {
            p.warn("anisotropic " + formatNumber(anisotropic) +
                   " became lamina's largest anisotropy, 0.99");
            anisotropic = 0.99;
        }
        // The same stretch as Mitsuba's (Kulla and Conty 2017): aspect = sqrt(1 - 0.9 a).
        m["anisotropy"] = anisotropic;
        if (metallic < 1)  // at metallic 1 there is no diffuse term
            p.warn(
                "anisotropic: the retro-reflection of lamina's Burley diffuse takes the roughness "
                "sqrt((alpha_x + alpha_y) / 2), slightly above Mitsuba's roughness");
    }
    // Mitsuba weighs the transmission (1 - metallic) spec_trans and the diffuse term
    // (1 - metallic)(1 - spec_trans); lamina's standard the first `transmission` and the second
    // (1 - metalness)(1 - transmission). The transmission is kept: a metal stays opaque.
    const double transmission = (1 - metallic) * specTrans;
    if (transmission > 0) {
        m["transmission"] = transmission;
        std::string differences;
        if (!isWhite(m["base_color"]))
            differences += ", untinted where Mitsuba tints it by sqrt(base_color)";
        if (metallic > 0)
            differences +=
                ", of weight (1 - metallic) spec_trans as in Mitsuba, but the diffuse term's is "
                "(1 - metallic)(1 - (1 - metallic) spec_trans) where Mitsuba's is (1 - "
                "metallic)(1 - spec_trans)";
        // Seen from inside, lamina's standard reflects with the Fresnel reflectance of the
        // outside (tests/interchange/mitsuba_principled_test.cpp finds its transmission exact).
        differences +=
            "; seen from inside, lamina reflects with the outside's Fresnel reflectance (no "
            "total internal reflection) and adds its diffuse share, where Mitsuba reflects "
            "(1 - metallic) spec_trans of the inside's Fresnel reflectance only";
        p.warn("spec_trans became lamina's transmission through the same rough dielectric" +
               differences);
    }
    if (givenNonZero(p, "spec_tint"))
        p.warn(
            "spec_tint is not supported: dropped (Mitsuba tints the dielectric reflection "
            "towards base_color; lamina's stays white)");
    dropUnsupportedLobes(p);
    samplingRates(p, {"diffuse_reflectance_sampling_rate", "main_specular_sampling_rate",
                      "clearcoat_sampling_rate"});
    // Mitsuba's diffuse, sheen and clearcoat are front-side lobes; without transmission (its
    // back side reflects (1 - metallic) spec_trans of the Fresnel reflectance) it is black
    // from behind.
    return {clearcoat(p, m, transmission > 0), transmission == 0};
}

TranslatedPrincipled principledThin(Plugin& p, std::vector<TranslatedTexture>& textures) {
    const Json baseColor = colorOrTexture(p, "base_color", textures).value_or(Json(0.5));
    const Json rough = roughness(p, textures, false);
    // principledthin.cpp multiplies its specular reflection and transmission by spec_trans.
    const double specTrans =
        constantWeight(p, "spec_trans", 0.0, 1.0, "lamina has no rough thin sheet that transmits");
    if (specTrans > 0)
        p.fail(
            "spec_trans above 0 is not supported on principledthin (a rough, tinted thin "
            "transmitting sheet; lamina's thin_dielectric is smooth and untinted): use "
            "thindielectric, or principled on a closed shape");
    // What only the specular lobes use: no effect at spec_trans 0.
    for (const char* name : {"anisotropic", "eta", "spec_tint"})
        givenNonZero(p, name);
    // diff_trans in [0, 2], halved: the share of (1 - spec_trans) that is Lambertian
    // transmission of base_color, the rest Burley's diffuse reflection.
    const double diffTrans =
        constantWeight(p, "diff_trans", 0.0, 2.0, "lamina's mix takes a number as its weight") / 2;
    dropUnsupportedLobes(p);
    samplingRates(p,
                  {"diffuse_reflectance_sampling_rate", "specular_reflectance_sampling_rate",
                   "specular_transmittance_sampling_rate", "diffuse_transmittance_sampling_rate"});
    const Json burley{{"type", "burley"}, {"reflectance", baseColor}, {"roughness", rough}};
    if (diffTrans == 0) return {burley, false};
    if (baseColor.is_object() && baseColor.contains("texture"))
        p.fail(
            "diff_trans with a textured base_color is not supported (lamina's mix takes "
            "untextured materials)");
    if (rough.is_object())
        p.fail(
            "diff_trans with a textured roughness is not supported (lamina's mix takes "
            "untextured materials)");
    const Json transmission{
        {"type", "diffuse_transmission"}, {"reflectance", 0}, {"transmittance", baseColor}};
    return {Json{{"type", "mix"}, {"a", burley}, {"b", transmission}, {"weight", diffTrans}},
            false};
}

}  // namespace lamina::render::mitsuba
