// Mitsuba 3 BSDFs -> lamina materials (mitsuba_bsdfs.h). Defaults are those of the plugin
// documentation in mitsuba3 src/bsdfs/*.cpp.
#include "mitsuba_bsdfs.h"

#include <array>
#include <cctype>
#include <cmath>
#include <utility>

#include "lamina/core/error.h"
#include "lamina/core/math.h"
#include "mitsuba_bsdf_parameters.h"
#include "mitsuba_principled.h"

namespace lamina::render::mitsuba {

namespace {

// Mitsuba's conductor presets (mitsuba3 src/bsdfs/conductor.cpp, data/ior/*.spd) that lamina
// has as named metals (measured tables, spectral/data/nk), by Mitsuba name -> lamina name.
constexpr std::array<std::pair<const char*, const char*>, 8> kConductorPresets{{
    {"Ag", "Ag"},
    {"Al", "Al"},
    {"Au", "Au"},
    {"Be", "Be"},
    {"Cr", "Cr"},
    {"Cu", "Cu"},
    {"W", "W"},
    {"Ni_palik", "Ni"},
}};

// A lamina optical constant (a number, an rgb triple or a spectrum [[nm, value], ...])
// divided by `d`.
Json dividedOptics(Json v, double d) {
    if (v.is_number()) return v.get<double>() / d;
    for (Json& e : v) {
        if (e.is_array())
            e[1] = e[1].get<double>() / d;
        else
            e = e.get<double>() / d;
    }
    return v;
}

Json conductor(Plugin& p, bool rough, std::vector<TranslatedTexture>& textures) {
    Json m{{"type", "conductor"}};
    const std::string material = p.string("material").value_or("none");
    const bool hasNk = p.has("eta") || p.has("k");
    if (hasNk && material != "none") p.fail("give either material or eta / k, not both");
    if (hasNk) {
        // Lamina's eta and k take a spectrum as the bare list [[nm, value], ...].
        auto optics = [&](const char* name, double fallback) {
            Json v = p.color(name).value_or(Json(fallback));
            return v.is_object() ? v["spectrum"] : v;
        };
        // Mitsuba 0.6's ext_eta (the index outside the metal, air by default): the Fresnel
        // equations take (eta + i k) / ext_eta.
        // (Mitsuba 3's conductors have no ext_eta: vacuum outside, as without it.)
        const double outside = p.has("ext_eta") ? indexOfRefraction(p, "ext_eta", "air") : 1.0;
        m["eta"] = dividedOptics(optics("eta", 0.0), outside);
        m["k"] = dividedOptics(optics("k", 1.0), outside);
    } else if (material == "none") {
        // eta 0, k 1: |(eta - 1 + ik) / (eta + 1 + ik)|^2 = 1 at every angle, a perfect mirror.
        m["f0"] = 1.0;
    } else {
        const char* lamina = nullptr;
        for (const auto& [mitsubaName, laminaName] : kConductorPresets)
            if (material == mitsubaName) lamina = laminaName;
        if (!lamina)
            p.fail(
                "material \"" + material +
                "\" has no lamina counterpart (lamina has Ag, Al, Au, Be, Cr, Cu, Ni_palik as Ni, "
                "W; give eta and k instead)");
        m["material"] = lamina;
        p.warn("material \"" + material + "\" became lamina's \"" + lamina +
               "\" (lamina's measured table; Mitsuba's tabulated data may differ slightly)");
    }
    if (!hasNk && p.has("ext_eta") && std::abs(indexOfRefraction(p, "ext_eta", "air") - 1) > 1e-3)
        p.fail("ext_eta other than air (1.000277) or vacuum is supported only with eta and k");
    refuseScale(p, "specular_reflectance");
    if (rough) microfacetRoughness(p, m, true, textures);
    return m;
}

Json dielectric(Plugin& p, const char* type, bool rough, const char* interior,
                std::vector<TranslatedTexture>& textures) {
    Json m{{"type", type}, {"ior", relativeIor(p, interior, "air")}};
    refuseScale(p, "specular_reflectance");
    refuseScale(p, "specular_transmittance");
    if (rough) microfacetRoughness(p, m, false, textures);
    return m;
}

Json plastic(Plugin& p, bool rough, bool insideTwoSided, std::vector<TranslatedTexture>& textures) {
    // The coat's roughness and the base's colour may be textured.
    Json base{
        {"type", "lambert"},
        {"reflectance", colorOrTexture(p, "diffuse_reflectance", textures).value_or(Json(0.5))}};
    Json m{{"type", "coated"}, {"ior", relativeIor(p, "polypropylene", "air")}, {"base", base}};
    refuseScale(p, "specular_reflectance");
    const bool nonlinear = p.boolean("nonlinear", false);
    if (rough) microfacetRoughness(p, m, false, textures);
    p.warn(std::string(rough ? "roughplastic" : "plastic") +
           " became lamina's coated (a dielectric coat over lambert, evaluated by a random walk "
           "that follows every internal reflection" +
           (nonlinear ? ", like Mitsuba's nonlinear model)"
                      : "; Mitsuba's default nonlinear=false model desaturates the colour less)"));
    warnOneSided(p, insideTwoSided, "coated");
    return m;
}

// mitsuba3 src/bsdfs/pplastic.cpp: f = F D G / (4 cos_i cos_o), a rough reflection with the
// exact Fresnel of eta, plus (1 - F(cos_i))(1 - F(cos_o)) rho / pi, added (no internal
// reflections, no 1 / eta^2). Lamina's `layered` has that rough interface (which polarises in
// the polarised mode, as Mitsuba's does; `coated` depolarises) and, with the albedo coupling,
// the diffuse term's shape with the rough interface's albedo E in place of F.
Json polarisedPlastic(Plugin& p, std::vector<TranslatedTexture>& textures) {
    if (const auto t = p.texture("diffuse_reflectance"))
        p.fail(
            "a textured diffuse_reflectance on pplastic is not supported (lamina's layered "
            "takes no texture)");
    if (p.texture("alpha") || p.texture("alpha_u") || p.texture("alpha_v"))
        p.fail("a textured alpha on pplastic is not supported (lamina's layered takes no texture)");
    const Json reflectance = p.color("diffuse_reflectance").value_or(Json(0.5));
    refuseScale(p, "specular_reflectance");
    double ior = 0;
    if (p.has("eta")) {
        if (p.has("int_ior") || p.has("ext_ior")) p.fail("give eta or int_ior / ext_ior, not both");
        if (p.texture("eta")) p.fail("a textured eta is not supported");
        ior = p.number("eta", 1.5);
        if (!(ior > 0)) p.fail("parameter \"eta\" must be > 0");
    } else {
        ior = relativeIor(p, "polypropylene", "air");
    }
    Json interface {
        {"ior", ior}, {"fresnel", "exact"}, { "g2", "separable" }
    };
    microfacetRoughness(p, interface, true, textures);
    interface["model"] = interface["distribution"];
    interface.erase("distribution");
    Json m{{"type", "layered"}, {"interface", interface}};
    if (reflectance == Json(0.0)) return m;  // the rough reflection alone: the same
    m["base"] = {{"type", "lambert"}, {"reflectance", reflectance}};
    m["coupling"] = "albedo";
    p.warn(
        "pplastic became lamina's layered: the same rough reflection; the diffuse term (1 - "
        "F(theta_i))(1 - F(theta_o)) rho / pi became (1 - E(theta_i))(1 - E(theta_o)) rho / (pi "
        "(1 - E_avg)), E the rough interface's albedo (about 1 / (1 - E_avg), 10% at eta 1.5, "
        "brighter), which depolarises where Mitsuba's refraction out polarises it weakly");
    return m;
}

// mitsuba3 src/bsdfs/polarizer.cpp: an ideal linear polariser whose absorbing axis is the
// surface's v direction turned by `theta` degrees, (sin theta, cos theta) in (u, v); so its
// transmission axis is (cos theta, -sin theta): lamina's `polariser` with that world `axis`.
// Unpolarised, both are a grey filter of transmittance / 2.
Json polariser(Plugin& p, const SurfaceDirections* surface) {
    if (!surface)
        p.fail(
            "a polarizer is supported as a rectangle's own BSDF only (its axis follows the "
            "surface's u and v directions, which lamina's polariser takes as a world axis)");
    // Mitsuba writes both as <spectrum value="90"/> or <float>: one number each here.
    const auto number = [&](const char* name, double fallback) {
        const auto c = p.color(name);
        if (c && !c->is_number())
            p.fail(std::string(name) +
                   " must be one number (a spectrum or colour is not supported)");
        return c ? c->get<double>() : fallback;
    };
    const double thetaDegrees = number("theta", 0.0), t = number("transmittance", 1.0);
    if (!(std::abs(thetaDegrees) <= 360)) p.fail("theta must be in [-360, 360] degrees");
    if (!(t >= 0 && t <= 1)) p.fail("transmittance must be in [0, 1]");
    if (!p.boolean("polarizing", true))
        p.fail("polarizing false (a neutral density filter) is not supported");
    const double a = radians(thetaDegrees);
    const glm::dvec3 axis = std::cos(a) * surface->u - std::sin(a) * surface->v;
    p.warn(
        "polarizer became lamina's polariser: the same at normal incidence; obliquely lamina "
        "projects the transmission axis across the ray, Mitsuba the absorbing axis (Korger et "
        "al. 2013)");
    Json m{{"type", "polariser"}, {"axis", Json::array({axis.x, axis.y, axis.z})}};
    if (t != 1.0) m["transmittance"] = t;
    return m;
}

bool mapsNormals(const Json& material) {
    return material.contains("displacement") || material.contains("normal_map");
}

// `bumpmap` and `normalmap` (mitsuba3 src/bsdfs/bumpmap.cpp, normalmap.cpp): the nested BSDF's
// material with lamina's `displacement` or `normal_map`.
TranslatedBsdf shadingNormalMap(Plugin& p, const MitsubaDocument& document,
                                Diagnostics& diagnostics, bool insideTwoSided, int depth) {
    const bool bump = p.type() == "bumpmap";
    const auto nested = p.objects("bsdf");
    if (nested.size() != 1) p.fail(p.type() + " needs one nested BSDF");
    const auto textures = p.objects("texture");
    if (textures.size() != 1) p.fail(p.type() + " needs one nested texture");
    if (!bump && !textures[0]->attribute("name"))
        p.fail("a normalmap's texture must be named \"normalmap\"");
    if (!bump && *textures[0]->attribute("name") != "normalmap")
        p.fail("a normalmap's texture must be named \"normalmap\", not \"" +
               *textures[0]->attribute("name") + "\"");
    const double scale = bump ? p.number("scale", 1.0) : 1.0;
    if (!(scale >= 0 && scale <= 1e6))
        p.fail("scale must be in [0, 1e6] for lamina (a negative height is not supported)");
    if (!p.boolean("flip_invalid_normals", true))
        p.warn(
            "flip_invalid_normals false became lamina's rule: a shading normal is always "
            "turned to the geometric normal's side");
    if (p.boolean("use_shadowing_function", true))
        p.warn(
            "the shadowing function of the perturbed normal (Conty Estevez et al. 2019) is "
            "not applied: lamina keeps Veach's shading-normal rules, which darken the "
            "terminator differently");
    TranslatedBsdf out =
        translateBsdf(*nested[0], document, diagnostics, insideTwoSided, depth + 1);
    if (mapsNormals(out.material)) p.fail("a bumpmap or normalmap inside another is not supported");
    bool raw = false;
    std::string name =
        translateTexture(*textures[0], TextureUse::Map, document, diagnostics, out.textures, &raw);
    if (!bump && !raw)
        p.fail(
            "a normalmap's bitmap decoded from sRGB is not supported: set raw to true "
            "(its texels are vectors)");
    if (bump) {
        if (scale != 1) {
            out.textures.push_back({name + " times " + formatNumber(scale),
                                    {{"type", "scale"}, {"texture", name}, {"scale", scale}},
                                    {}});
            name = out.textures.back().name;
        }
        out.material["displacement"] = {{"texture", name}};
        p.warn(
            "bumpmap became the material's displacement: lamina's bump includes the h dn/du "
            "term Mitsuba leaves out (the same on flat faces; curved ones shade slightly "
            "differently where the height is not 0), and takes the image's first channel "
            "where Mitsuba takes an RGB image's luminance");
    } else {
        out.material["normal_map"] = {{"texture", name}};
    }
    return out;
}

}  // namespace

TranslatedBsdf translateBsdf(const Element& bsdf, const MitsubaDocument& document,
                             Diagnostics& diagnostics, bool insideTwoSided, int depth,
                             const SurfaceDirections* surface) {
    Plugin p(bsdf, document, diagnostics);
    if (depth > 16) p.fail("BSDFs nested deeper than 16 (does a <ref> refer to its own BSDF?)");
    const std::string& type = p.type();
    TranslatedBsdf out;
    if (type == "diffuse") {
        out.material = {
            {"type", "lambert"},
            {"reflectance", colorOrTexture(p, "reflectance", out.textures).value_or(Json(0.5))}};
        warnOneSided(p, insideTwoSided, "lambert");
    } else if (type == "conductor" || type == "roughconductor") {
        out.material = conductor(p, type == "roughconductor", out.textures);
        warnOneSided(p, insideTwoSided, "conductor");
    } else if (type == "dielectric") {
        out.material = dielectric(p, "dielectric", false, "bk7", out.textures);
    } else if (type == "roughdielectric") {
        out.material = dielectric(p, "dielectric", true, "bk7", out.textures);
    } else if (type == "thindielectric") {
        out.material = dielectric(p, "thin_dielectric", false, "bk7", out.textures);
    } else if (type == "plastic" || type == "roughplastic") {
        out.material = plastic(p, type == "roughplastic", insideTwoSided, out.textures);
    } else if (type == "pplastic") {
        out.material = polarisedPlastic(p, out.textures);
        warnOneSided(p, insideTwoSided, "layered");
    } else if (type == "principled" || type == "principledthin") {
        const TranslatedPrincipled t =
            type == "principled" ? principled(p, out.textures) : principledThin(p, out.textures);
        out.material = t.material;
        if (t.oneSided) warnOneSided(p, insideTwoSided, "standard");
    } else if (type == "twosided") {
        // Lamina's reflection models are two-sided already (shaded with the normal facing wo),
        // so twosided(X) is X. Mitsuba's form with two BSDFs (front, back) has no counterpart.
        const auto nested = p.objects("bsdf");
        if (nested.size() != 1)
            p.fail("twosided with " + std::to_string(nested.size()) +
                   " BSDFs is not supported (lamina takes one, used on both sides)");
        out = translateBsdf(*nested[0], document, diagnostics, true, depth + 1);
    } else if (type == "blendbsdf") {
        const auto nested = p.objects("bsdf");
        if (nested.size() != 2) p.fail("blendbsdf needs two nested BSDFs");
        const auto weight = p.optionalNumber("weight");
        if (!weight && p.has("weight")) p.fail("a textured weight is not supported");
        const double w = weight.value_or(0.5);
        if (!(w >= 0 && w <= 1)) p.fail("weight must be in [0, 1]");
        TranslatedBsdf a =
            translateBsdf(*nested[0], document, diagnostics, insideTwoSided, depth + 1);
        TranslatedBsdf b =
            translateBsdf(*nested[1], document, diagnostics, insideTwoSided, depth + 1);
        if (a.alpha || b.alpha) p.fail("a mask inside blendbsdf is not supported");
        if (mapsNormals(a.material) || mapsNormals(b.material))
            p.fail(
                "a bumpmap or normalmap inside blendbsdf is not supported (lamina's maps "
                "belong to the material a shape uses)");
        if (!a.textures.empty() || !b.textures.empty())
            p.fail(
                "a textured BSDF inside blendbsdf is not supported (lamina's mix takes "
                "untextured materials)");
        out.textures = std::move(a.textures);
        out.textures.insert(out.textures.end(), b.textures.begin(), b.textures.end());
        // Mitsuba: (1 - weight) first + weight second; lamina's mix: (1 - w) a + w b.
        out.material = {{"type", "mix"}, {"a", a.material}, {"b", b.material}, {"weight", w}};
    } else if (type == "mask") {
        const auto nested = p.objects("bsdf");
        if (nested.size() != 1) p.fail("mask needs one nested BSDF");
        out = translateBsdf(*nested[0], document, diagnostics, insideTwoSided, depth + 1);
        if (out.alpha) p.fail("a mask inside a mask is not supported");
        // A textured opacity is the shape's textured alpha: Mitsuba's mask passes a ray on
        // with probability 1 - opacity at the hit, as lamina's stochastic alpha test does.
        if (const auto t = p.texture("opacity")) {
            out.alpha = Json{{"texture", translateTexture(*t->texture, TextureUse::Opacity,
                                                          document, diagnostics, out.textures)}};
        } else {
            const auto opacity = p.color("opacity");
            if (opacity && !opacity->is_number())
                p.fail(
                    "opacity must be one number or a texture (a coloured opacity is not "
                    "supported)");
            const double alpha = opacity ? opacity->get<double>() : 0.5;
            if (!(alpha >= 0 && alpha <= 1)) p.fail("opacity must be in [0, 1]");
            if (alpha < 1) out.alpha = alpha;
        }
    } else if (type == "null") {
        p.fail(
            "a null BSDF is only supported as a shape's own BSDF (an index-matched "
            "boundary), not inside another BSDF");
    } else if (type == "measured") {
        // mitsuba3 src/bsdfs/measured.cpp: an RGL .bsdf file (lamina's `measured`, docs/bsdf.md).
        // The path is written absolute: this translation has no document directory to write it
        // relative to.
        const auto file = p.file("filename");
        if (!file) p.fail("measured needs \"filename\"");
        out.material = {{"type", "measured"}, {"filename", file->string()}};
        warnOneSided(p, insideTwoSided, "measured");
    } else if (type == "polarizer") {
        out.material = polariser(p, surface);
    } else if (type == "bumpmap" || type == "normalmap") {
        out = shadingNormalMap(p, document, diagnostics, insideTwoSided, depth);
    } else if (type == "hair") {
        out.material = hairMaterial(p);
    } else {
        p.fail("the BSDF plugin \"" + type +
               "\" is not supported (diffuse, conductor, roughconductor, dielectric, "
               "roughdielectric, thindielectric, plastic, roughplastic, pplastic, principled, "
               "principledthin, twosided, blendbsdf, mask, bumpmap, normalmap, measured, "
               "polarizer, hair)");
    }
    p.finish();
    return out;
}

}  // namespace lamina::render::mitsuba
