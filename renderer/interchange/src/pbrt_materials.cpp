// pbrt-v4 materials and textures -> lamina materials and textures (pbrt-v4 materials.cpp and
// textures.cpp give the parameters and their defaults). Each is translated when a shape first
// uses it, as pbrt-v4 would create it.
#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

constexpr int kMaxMaterialNesting = 16;  // mix of mix of ...: a cycle is refused

const MaterialDef* findMaterial(const ParsedScene& scene, const std::string& name) {
    for (const MaterialDef& m : scene.materials)
        if (m.name == name) return &m;
    return nullptr;
}

// The texture a roughness parameter names, or nullptr when it is a number or absent.
const Param* roughnessTexture(const ParamList& params, const std::string& name) {
    const Param* p = params.find(name);
    if (!p || canonicalParamType(p->type) != "texture") return nullptr;
    if (p->strings.size() != 1) params.fail(*p, "expected one texture name");
    return p;
}

// A textured roughness (`roughness`, or `uroughness` and `vroughness` naming one texture) as
// lamina's textured `roughness`, which is sqrt(alpha): a `power` texture of the looked-up value,
// applied after the lookup as pbrt-v4 remaps it (exponent 1/4 with remaproughness, whose alpha is
// sqrt(roughness), else 1/2). Returns false when no roughness is textured.
bool texturedRoughness(TranslationContext& ctx, const Entity& e, const std::string& prefix,
                       bool remap, Json& material) {
    const ParamList& params = e.params;
    const Param* r = roughnessTexture(params, prefix + "roughness");
    const Param* u = roughnessTexture(params, prefix + "uroughness");
    const Param* v = roughnessTexture(params, prefix + "vroughness");
    if (!r && !u && !v) return false;
    const auto name = [](const Param* p) { return p ? p->strings[0] : std::string(); };
    const bool numberBeside =
        (!u && params.has(prefix + "uroughness")) || (!v && params.has(prefix + "vroughness"));
    const std::string uName = u ? name(u) : name(r), vName = v ? name(v) : name(r);
    if (numberBeside || uName != vName)
        ctx.fail((u   ? u
                  : v ? v
                      : r)
                     ->location,
                 "an anisotropic textured roughness is not supported (lamina's textured "
                 "roughness is isotropic: give roughness, or one texture to uroughness and "
                 "vroughness)");
    const Param& used = u ? *u : r ? *r : *v;
    const std::string texture = useTexture(ctx, uName, "float", used.location);
    const double exponent = remap ? 0.25 : 0.5;
    const std::string remapped = texture + (remap ? " ^ 1/4" : " ^ 1/2");
    ctx.document["textures"][remapped] = {
        {"type", "power"}, {"texture", texture}, {"exponent", exponent}};
    material["roughness"] = {{"texture", remapped}};
    return true;
}

// pbrt-v4's roughness parameters (materials.cpp): `roughness`, or `uroughness` and
// `vroughness` (each defaulting to `roughness`, itself 0), and `remaproughness` (true), which
// maps a roughness r to the Trowbridge-Reitz alpha sqrt(r)
// (TrowbridgeReitzDistribution::RoughnessToAlpha, util/scattering.h). lamina's GGX is the
// same distribution with the same alpha. `textureAllowed`: the lamina material takes a
// textured roughness (conductors, dielectrics and a coat; not a coat's base).
void roughness(TranslationContext& ctx, const Entity& e, const std::string& prefix, Json& material,
               bool textureAllowed) {
    const ParamList& params = e.params;
    const bool remap = params.boolean("remaproughness", true);
    if (textureAllowed && texturedRoughness(ctx, e, prefix, remap, material)) return;
    const double r = constantNumber(params, prefix + "roughness", 0.0);
    const double u = constantNumber(params, prefix + "uroughness", r);
    const double v = constantNumber(params, prefix + "vroughness", r);
    auto alpha = [&](double x) {
        if (x < 0) ctx.fail(e.location, "a roughness is negative");
        const double a = remap ? std::sqrt(x) : x;
        // pbrt-v4's Trowbridge-Reitz takes any alpha; lamina's microfacet models stop at 1
        // (their albedo tables and schema), where the lobe is already close to uniform.
        if (a > 1) {
            ctx.warn(e.location, "a roughness of alpha " + std::to_string(a) +
                                     " became lamina's largest, alpha 1 (a slightly less "
                                     "diffuse lobe)");
            return 1.0;
        }
        return a;
    };
    if (u == v) {
        if (u != 0) material["alpha"] = alpha(u);
        return;
    }
    material["alpha_x"] = alpha(u);
    material["alpha_y"] = alpha(v);
    ctx.warn(e.location,
             "anisotropic roughness became alpha_x along the surface's u tangent "
             "and alpha_y along v");
}

// pbrt-v4's bump and normal maps, which every material but mix and interface takes
// (materials.cpp): lamina's `displacement` and `normal_map` on the material. pbrt-v4 reads a
// normal map's image as linear and uses it instead of a displacement (Material::GetBSDF).
void shadingNormalMaps(TranslationContext& ctx, const Entity& e, Json& material) {
    const ParamList& params = e.params;
    const Param* displacement = params.find("displacement");
    const Param* normalMap = params.find("normalmap");
    if (normalMap) {
        params.expectType(*normalMap, {"string"});
        if (normalMap->strings.size() != 1) params.fail(*normalMap, "expected one file name");
        const std::string name = "normal map " + normalMap->strings[0];
        ctx.document["textures"][name] = {{"type", "image"},
                                          {"file", ctx.filePath(params, *normalMap)},
                                          {"color_space", "linear"}};
        material["normal_map"] = {{"texture", name}};
    }
    if (!displacement) return;
    params.expectType(*displacement, {"float", "texture"});
    if (displacement->strings.size() + displacement->numbers.size() != 1)
        params.fail(*displacement, "expected one value");
    if (normalMap) {
        ctx.warn(displacement->location,
                 "displacement ignored: the material's normalmap replaces it, as in pbrt-v4");
    } else if (canonicalParamType(displacement->type) == "float") {
        // A constant height moves no normal of a flat face or a sphere; pbrt-v4's h dn/du term
        // turns interpolated vertex normals slightly, which lamina's constant-free key cannot.
        if (displacement->numbers[0] != 0)
            ctx.warn(displacement->location,
                     "a constant displacement was dropped (it turns only interpolated vertex "
                     "normals, slightly, in pbrt-v4)");
    } else {
        material["displacement"] = {{"texture", useTexture(ctx, displacement->strings[0], "float",
                                                           displacement->location)}};
        ctx.warn(displacement->location,
                 "the bump map's slopes are differences over 0.0005 in uv (pbrt-v4 differences "
                 "over the pixel's footprint with ray differentials: bumps finer than a pixel "
                 "look sharper in lamina)");
    }
}

Json translateMaterial(TranslationContext& ctx, const MaterialDef& def, int depth);

Json materialByName(TranslationContext& ctx, const std::string& name, const Location& at,
                    int depth) {
    const MaterialDef* m = findMaterial(ctx.scene, name);
    if (!m) ctx.fail(at, "no material named \"" + name + "\"");
    if (depth > kMaxMaterialNesting)
        ctx.fail(at, "materials nest more than " + std::to_string(kMaxMaterialNesting) +
                         " deep (does a mix material contain itself?)");
    if (const auto it = ctx.translatedMaterials.find(name); it != ctx.translatedMaterials.end())
        return it->second;
    Json translated = translateMaterial(ctx, *m, depth + 1);
    ctx.translatedMaterials[name] = translated;
    return translated;
}

Json coated(TranslationContext& ctx, const Entity& e, const std::string& roughnessPrefix,
            const std::string& etaName, double& ior) {
    const ParamList& params = e.params;
    // pbrt-v4's coated materials (materials.cpp: CoatedDiffuseMaterial::Create,
    // CoatedConductorMaterial::Create): thickness 0.01, albedo 0, g 0, maxdepth 10,
    // nsamples 1; the medium between the layers has unit extinction (LayeredBxDF::Tr), so
    // the thickness is lamina's optical thickness.
    Json m{{"type", "coated"}};
    const Json iorJson = dielectricIor(ctx, params, etaName, e.location);
    if (!iorJson.is_number())
        ctx.fail(e.location, "a coat's index must be a number in lamina's coated material");
    ior = iorJson.get<double>();
    m["ior"] = ior;
    roughness(ctx, e, roughnessPrefix, m, true);
    m["thickness"] = constantNumber(params, "thickness", 0.01);
    m["albedo"] = colour(ctx, e, "albedo", 0.0, false);
    m["g"] = constantNumber(params, "g", 0.0);
    // pbrt-v4's walk stops after maxdepth events (10 by default); lamina's has no cap unless
    // given, so the cap is written out to render what pbrt-v4 renders.
    const int maxDepth = params.integer("maxdepth", 10);
    m["max_depth"] = maxDepth;
    m["samples"] = params.integer("nsamples", 1);
    ctx.warn(e.location,
             e.type + " became lamina's coated with max_depth " + std::to_string(maxDepth) +
                 " (pbrt-v4's maxdepth: its random walk stops there, which darkens bright bases; "
                 "remove max_depth for lamina's unbiased walk, which ends by Russian roulette)");
    return m;
}

// pbrt-v4's HairMaterial (materials.cpp): the absorption from `sigma_a`, else `reflectance`
// (or `color`), else `eumelanin` and `pheomelanin`, else eumelanin 1.3; pbrt-v4 ignores the
// later ones with a warning, and so does the translation (lamina's hair takes one).
Json hair(TranslationContext& ctx, const Entity& e) {
    const ParamList& params = e.params;
    Json m{{"type", "hair"}};
    const char* reflectanceName = params.has("reflectance") ? "reflectance" : "color";
    const bool sigma = params.has("sigma_a"), reflectance = params.has(reflectanceName);
    const bool melanin = params.has("eumelanin") || params.has("pheomelanin");
    if (sigma) {
        const Json s = colour(ctx, e, "sigma_a", 0.0, false);
        if (s.is_object())
            ctx.fail(e.location, "hair: \"sigma_a\" as a spectrum is not supported (give rgb)");
        m["sigma_a"] = s.is_number() ? Json::array({s, s, s}) : s;
    } else if (reflectance) {
        m["reflectance"] = colour(ctx, e, reflectanceName, 0.5, false);
    } else if (melanin) {
        m["eumelanin"] = constantNumber(params, "eumelanin", 0.0);
        m["pheomelanin"] = constantNumber(params, "pheomelanin", 0.0);
    }
    for (const std::string ignored : {"reflectance", "color", "eumelanin", "pheomelanin"}) {
        const bool used = (reflectance && !sigma && ignored == reflectanceName) ||
                          (melanin && !sigma && !reflectance && ignored.ends_with("melanin"));
        if (!params.has(ignored) || used) continue;
        params.find(ignored);
        ctx.warn(e.location, "hair: \"" + ignored +
                                 "\" ignored, as pbrt-v4 does: the absorption is given by an "
                                 "earlier parameter (sigma_a, then reflectance, then melanin)");
    }
    m["eta"] = constantNumber(params, "eta", 1.55);
    m["beta_m"] = constantNumber(params, "beta_m", 0.3);
    m["beta_n"] = constantNumber(params, "beta_n", 0.3);
    m["alpha"] = constantNumber(params, "alpha", 2.0);
    return m;
}

// pbrt-v4's SubsurfaceMaterial (materials.cpp, SubsurfaceMaterial::Create): a dielectric
// boundary (a float eta, default 1.33; roughness as a dielectric's) around a homogeneous
// medium given by a measured `name` (sigma_a and the reduced sigma_s, g = 0), by `sigma_a` and
// `sigma_s`, or by pbrt-v4's defaults, all times `scale`. pbrt-v4 renders the light beneath the
// surface with a tabulated BSSRDF (photon beam diffusion); lamina renders the volumetric light
// transport that the BSSRDF approximates: the shapes using the material hold the medium
// (subsurfaceInteriors) and their surface is the dielectric.
Json subsurface(TranslationContext& ctx, const MaterialDef& def) {
    const Entity& e = def.entity;
    const ParamList& params = e.params;
    Json medium{{"type", "homogeneous"}};
    double g = params.number("g", 0.0);
    const std::string name = params.string("name", "");
    if (!name.empty()) {
        const auto measured = measuredMediumCoefficients(name);
        if (!measured)
            ctx.fail(e.location, "subsurface: no measured medium \"" + name +
                                     "\" (pbrt-v4's names, e.g. \"Skin1\")");
        if (g != 0)
            ctx.warn(e.location,
                     "subsurface: \"g\" ignored with a named medium (its sigma_s is the "
                     "reduced one, for g = 0, as in pbrt-v4)");
        g = 0;
        medium["sigma_a"] = measured->first;
        medium["sigma_s"] = measured->second;
    } else if (params.find("sigma_a") || params.find("sigma_s")) {
        if (!params.find("sigma_a") || !params.find("sigma_s"))
            ctx.fail(e.location, "subsurface: give both sigma_a and sigma_s (as pbrt-v4 requires)");
        medium["sigma_a"] = mediumCoefficient(ctx, params, "sigma_a");
        medium["sigma_s"] = mediumCoefficient(ctx, params, "sigma_s");
    } else if (params.find("reflectance")) {
        ctx.fail(e.location,
                 "subsurface: \"reflectance\" (with \"mfp\") is not supported: pbrt-v4 inverts "
                 "its BSSRDF's table for the coefficients; give \"sigma_a\" and \"sigma_s\", or "
                 "a measured \"name\"");
    } else {
        medium["sigma_a"] = Json::array({0.0011, 0.0024, 0.014});
        medium["sigma_s"] = Json::array({2.55, 3.21, 3.77});
    }
    const double scale = constantNumber(params, "scale", 1.0);
    if (!(scale >= 0) || !std::isfinite(scale))
        ctx.fail(e.location, "subsurface: \"scale\" must be finite and >= 0");
    medium["scale"] = scale;
    if (!(std::abs(g) < 1))
        ctx.fail(e.location,
                 "subsurface: \"g\" must lie in (-1, 1): lamina's Henyey-Greenstein phase "
                 "function has no delta limit");
    medium["g"] = g;
    const std::string mediumName = "subsurface of " + def.name;
    ctx.document["media"][mediumName] = medium;
    ctx.writtenMedia.insert(mediumName);
    ctx.subsurfaceInteriors[def.name] = mediumName;
    Json m{{"type", "dielectric"}, {"ior", constantNumber(params, "eta", 1.33)}};
    roughness(ctx, e, "", m, true);
    ctx.warn(e.location,
             "subsurface: rendered as the light transport in its homogeneous medium behind a "
             "dielectric boundary, which pbrt-v4's tabulated BSSRDF approximates (each "
             "scattering inside counts towards max_depth: raise it for deep translucency)");
    return m;
}

Json translateMaterial(TranslationContext& ctx, const MaterialDef& def, int depth) {
    const Entity& e = def.entity;
    const ParamList& params = e.params;
    params.string("type", "");  // MakeNamedMaterial's type, already read
    Json m;
    if (e.type == "diffuse") {
        m = {{"type", "lambert"}, {"reflectance", colour(ctx, e, "reflectance", 0.5, true)}};
    } else if (e.type == "conductor") {
        m = {{"type", "conductor"}};
        conductorOptics(ctx, e, "", 1.0, m);
        roughness(ctx, e, "", m, true);
    } else if (e.type == "dielectric" || e.type == "thindielectric") {
        const bool thin = e.type == "thindielectric";
        m = {{"type", thin ? "thin_dielectric" : "dielectric"},
             {"ior", dielectricIor(ctx, params, "eta", e.location)}};
        if (!thin) roughness(ctx, e, "", m, true);
    } else if (e.type == "coateddiffuse") {
        double ior = 1.5;
        m = coated(ctx, e, "", "eta", ior);
        // A textured reflectance textures the base (lamina's coated takes textures through
        // its base, material_kind.h's texturedThrough).
        m["base"] = {{"type", "lambert"},
                     {"reflectance", colour(ctx, e, "reflectance", 0.5, true)}};
    } else if (e.type == "coatedconductor") {
        double ior = 1.5;
        m = coated(ctx, e, "interface.", "interface.eta", ior);
        Json base{{"type", "conductor"}};
        // pbrt-v4 divides the conductor's eta and k by the coat's index
        // (CoatedConductorMaterial::GetBxDF); lamina's base optics are relative to the coat.
        conductorOptics(ctx, e, "conductor.", ior, base);
        roughness(ctx, e, "conductor.", base, false);
        m["base"] = base;
    } else if (e.type == "diffusetransmission") {
        const double scale = constantNumber(params, "scale", 1.0);
        auto scaled = [&](Json c) {
            if (scale == 1) return c;
            if (c.is_number()) return Json(c.get<double>() * scale);
            if (c.is_array()) {
                for (auto& x : c)
                    x = x.get<double>() * scale;
                return c;
            }
            ctx.fail(e.location, "diffusetransmission: \"scale\" with a spectrum is not supported");
        };
        m = {{"type", "diffuse_transmission"},
             {"reflectance", scaled(colour(ctx, e, "reflectance", 0.25, false))},
             {"transmittance", scaled(colour(ctx, e, "transmittance", 0.25, false))}};
    } else if (e.type == "mix") {
        const Param* names = params.find("materials");
        if (!names) ctx.fail(e.location, "mix: no \"string materials\" parameter");
        params.expectType(*names, {"string"});
        if (names->strings.size() != 2) params.fail(*names, "expected two material names");
        // pbrt-v4's MixMaterial picks materials[1] with probability `amount` (ChooseMaterial):
        // in expectation lamina's (1 - weight) a + weight b.
        const double amount = constantNumber(params, "amount", 0.5);
        Json a = materialByName(ctx, names->strings[0], names->location, depth);
        Json b = materialByName(ctx, names->strings[1], names->location, depth);
        for (const std::string& mixed : names->strings)
            if (ctx.subsurfaceInteriors.count(mixed))
                ctx.fail(e.location,
                         "mix: a subsurface material cannot be mixed (its medium "
                         "belongs to the shape)");
        if (a.is_null() || b.is_null())
            ctx.fail(e.location, "mix: an interface material cannot be mixed");
        for (const Json* mixed : {&a, &b})
            if (mixed->contains("displacement") || mixed->contains("normal_map"))
                ctx.fail(e.location,
                         "mix: a material with a bump or normal map cannot be mixed (lamina's "
                         "maps belong to the material a shape uses)");
        m = {{"type", "mix"}, {"a", a}, {"b", b}, {"weight", std::clamp(amount, 0.0, 1.0)}};
    } else if (e.type == "measured") {
        // pbrt-v4's MeasuredMaterial: an RGL .bsdf file (lamina's `measured`, docs/bsdf.md).
        const Param* file = params.find("filename");
        if (!file) ctx.fail(e.location, "measured: no \"string filename\" parameter");
        params.expectType(*file, {"string"});
        m = {{"type", "measured"}, {"filename", ctx.filePath(params, *file)}};
    } else if (e.type == "hair") {
        m = hair(ctx, e);
    } else if (e.type == "subsurface") {
        // A mix's materials are translated one level deeper than a shape's.
        if (depth > 1)
            ctx.fail(e.location,
                     "a subsurface material cannot be mixed (its medium belongs to the shape)");
        m = subsurface(ctx, def);
    } else if (e.type == "interface" || e.type == "" || e.type == "none") {
        // pbrt-v4 reads Material "" and "none" as "interface" (Material::Create).
        params.refuseUnused();
        return nullptr;
    } else {
        ctx.fail(e.location, "material \"" + e.type +
                                 "\" is not supported (lamina reads diffuse, conductor, "
                                 "dielectric, thindielectric, coateddiffuse, coatedconductor, "
                                 "diffusetransmission, measured, hair, subsurface, mix and "
                                 "interface)");
    }
    if (e.type != "mix" && e.type != "hair") shadingNormalMaps(ctx, e, m);
    params.refuseUnused();
    return m;
}

}  // namespace

// A reflectance-like spectrum parameter: a number, [r, g, b], {"spectrum": pairs} or, where
// lamina takes one, {"texture": name}.
Json colour(TranslationContext& ctx, const Entity& e, const std::string& name, const Json& fallback,
            bool textureAllowed) {
    const ParamList& params = e.params;
    const Param* p = params.find(name);
    if (!p) return fallback;
    params.expectType(*p, {"float", "rgb", "spectrum", "texture"});
    const std::string type = canonicalParamType(p->type);
    if (type == "texture") {
        if (!textureAllowed)
            params.fail(*p,
                        "as a texture is not supported here (lamina textures reflectances "
                        "of diffuse materials and roughness)");
        if (p->strings.size() != 1) params.fail(*p, "expected one texture name");
        return Json{{"texture", useTexture(ctx, p->strings[0], "spectrum", p->location)}};
    }
    if (type == "float") {
        if (p->numbers.size() != 1) params.fail(*p, "expected one number");
        return p->numbers[0];
    }
    if (type == "rgb") {
        if (p->numbers.size() != 3) params.fail(*p, "expected three numbers");
        return Json::array({p->numbers[0], p->numbers[1], p->numbers[2]});
    }
    if (!p->strings.empty()) params.fail(*p, "a named spectrum is not supported as a reflectance");
    if (p->numbers.size() < 4 || p->numbers.size() % 2 != 0)
        params.fail(*p, "expected (wavelength, value) pairs");
    Json list = Json::array();
    for (std::size_t i = 0; i + 1 < p->numbers.size(); i += 2)
        list.push_back({p->numbers[i], p->numbers[i + 1]});
    return Json{{"spectrum", list}};
}

double constantNumber(const ParamList& params, const std::string& name, double fallback) {
    const Param* p = params.find(name);
    if (!p) return fallback;
    if (canonicalParamType(p->type) == "texture")
        params.fail(*p, "as a texture is not supported (lamina takes a number here)");
    return params.number(name, fallback);
}

std::string useMaterial(TranslationContext& ctx, const std::string& name, const Location& usedAt) {
    Json& materials = ctx.document["materials"];
    // An object even when every material used is "interface" (which writes none).
    if (!materials.is_object()) materials = Json::object();
    if (name.empty()) {
        // pbrt-v4's initial graphics state: a diffuse material of reflectance 0.5
        // (scene.cpp, BasicSceneBuilder's constructor).
        if (!ctx.writtenMaterials.count("pbrt_default")) {
            materials["pbrt_default"] = {{"type", "lambert"}, {"reflectance", 0.5}};
            ctx.writtenMaterials.insert("pbrt_default");
        }
        return "pbrt_default";
    }
    if (ctx.writtenMaterials.count(name)) return materials.contains(name) ? name : "";
    ctx.writtenMaterials.insert(name);
    Json m = materialByName(ctx, name, usedAt, 0);
    if (m.is_null()) return "";
    materials[name] = std::move(m);
    return name;
}

}  // namespace lamina::render::pbrt
