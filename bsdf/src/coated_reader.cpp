// `coated`: a dielectric coat over a base material without transmission, with an optional
// homogeneous medium between them (docs/bsdf.md, "coated").
#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/material_kind.h"
#include "material_readers.h"

namespace lamina {

namespace {

constexpr auto kCoatNdfNames = kNdfKindNames.subset(std::array{NdfKind::Ggx, NdfKind::Beckmann});

}  // namespace

MaterialModel readCoated(const JsonReader& r) {
    CoatedMaterial c;
    c.ior = r.number("ior", 1.5, Range::positive());
    c.microfacet.ndf = r.choice("distribution", NdfKind::Ggx, kCoatNdfNames);
    readRoughness(r, 0.0, c.microfacet);
    readMicrofacetSwitches(r, c.microfacet, false);
    if (!r.has("base")) r.failAt("base", "missing; expected a material without transmission");
    c.base = std::make_shared<MaterialDesc>(parseMaterial(r.child("base")));
    if (materialTransmits(*c.base))
        r.failAt("base",
                 "expected a material without transmission (no dielectric or thin_dielectric, "
                 "no diffuse_transmission, no polariser or retarder, no standard or layered "
                 "transmission)");
    c.thickness = r.number("thickness", 0.0, {0.0, 1e3});
    c.albedo = readColor(r, "albedo", 0.0);
    c.g = r.number("g", 0.0, {-0.99, 0.99});
    // Under a smooth coat, a path whose last non-delta event (a diffuse bounce, a scattering)
    // is followed by delta bounces between the coat and a specular base reaches wi along one
    // direction only: neither the walk's sampling nor its connections find it, so eval would
    // miss it. Such stacks are refused rather than rendered too dark.
    const std::uint32_t baseFlags = buildBxdf(*c.base, SpectrumContext<Rgb<double>>{})->flags();
    c.baseHasDeltaLobe = isSpecular(baseFlags);
    const bool smoothCoat = std::max(c.microfacet.alphaX, c.microfacet.alphaY) < kSmoothAlpha;
    const bool scatters = c.thickness > 0 && (c.albedo.rgb.maxValue() > 0 || c.albedo.spectrum);
    if (smoothCoat && isSpecular(baseFlags) &&
        (scatters || (baseFlags & (kLobeDiffuse | kLobeGlossy)) != 0))
        r.failAt("base",
                 "a smooth coat over a base with a smooth (delta) lobe needs a base of "
                 "delta lobes only and no scattering medium; give the coat or the base "
                 "a roughness");
    // No cap unless given: the walk then ends by Russian roulette and is unbiased.
    c.maxDepth = r.integer("max_depth", 0, 1, kMaxCoatedDepth);
    c.samples = r.integer("samples", 1, 1, 256);
    return c;
}

// The registrations of these types (material_kind.h; listed in material_kinds.cpp).

namespace {

std::vector<const MaterialDesc*> coatedNested(const MaterialModel& model) {
    return {model.as<CoatedMaterial>().base.get()};
}

constexpr TexturableKey kCoatedTextured[] = {{"roughness", TexturedParameter::Roughness}};

// The coat's own roughness may be textured (a textured roughness inside the base is refused:
// readTexturedMaterial), so a textured roughness is the coat's; over a base with a delta lobe
// it stays above the smooth limit, where readCoated would have refused the stack. The base's
// colour texture sets a copy of the base, so that the scene's material stays as it was read.
void texturedCoated(MaterialModel& model, const TexturedValues& t) {
    auto& c = model.as<CoatedMaterial>();
    if (t.roughness) {
        double alpha = *t.roughness * *t.roughness;
        if (c.baseHasDeltaLobe) alpha = std::max(alpha, double(kSmoothAlpha));
        c.microfacet.alphaX = c.microfacet.alphaY = alpha;
    }
    if (!t.color) return;
    auto base = std::make_shared<MaterialDesc>(*c.base);
    findMaterialKind(base->type)->applyTextures(base->model, TexturedValues{t.color, std::nullopt});
    c.base = std::move(base);
}

}  // namespace

extern const MaterialKind kCoatedMaterial{
    .name = "coated",
    .listPosition = 130,
    .read = readCoated,
    .schema = R"json({
  "type": "object",
  "description": "A dielectric coat (smooth or rough) over a base without transmission, with an optional homogeneous Henyey-Greenstein medium between them, evaluated by a random walk (docs/bsdf.md, \"coated\").",
  "required": ["type", "base"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "coated"},
    "ior": {"type": "number", "exclusiveMinimum": 0, "default": 1.5},
    "distribution": {"enum": ["ggx", "beckmann"]},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
    "g2": {"$ref": "#/$defs/g2"},
    "base": {"$ref": "#/$defs/material"},
    "thickness": {"type": "number", "minimum": 0, "maximum": 1000, "default": 0},
    "albedo": {"$ref": "#/$defs/colour"},
    "g": {"type": "number", "minimum": -0.99, "maximum": 0.99, "default": 0},
    "max_depth": {"type": "integer", "minimum": 1, "maximum": 1048576, "description": "The most events of a walk (a longer path is absorbed: f is biased low). Absent: no cap, the walk ends by Russian roulette (unbiased)."},
    "samples": {"type": "integer", "minimum": 1, "maximum": 256, "default": 1}
  },
  "examples": [
    {
      "type": "coated",
      "ior": 1.5,
      "roughness": 0.1,
      "base": {"type": "lambert", "reflectance": [0.6, 0.1, 0.1]}
    },
    {
      "type": "coated",
      "roughness": 0.2,
      "thickness": 0.1,
      "albedo": [0.8, 0.5, 0.2],
      "g": 0.3,
      "max_depth": 16,
      "samples": 2,
      "base": {"type": "conductor", "material": "Au", "roughness": 0.3}
    }
  ]
})json",
    .texturable = kCoatedTextured,
    .applyTextures = texturedCoated,
    .nested = coatedNested,
    .texturedThrough = "base",
    .transmits = [](const MaterialModel& m) {
        return materialTransmits(*m.as<CoatedMaterial>().base);
    }};

}  // namespace lamina
