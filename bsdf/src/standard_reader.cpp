// `standard` and `layered`: two spellings of one stack, a specular interface over a diffuse
// base with transmission, both read into StandardMaterial (docs/bsdf.md, "Materials").
#include <cmath>

#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/standard.h"
#include "material_readers.h"

namespace lamina {

namespace {

// The interface's lobe: `model` maps to the Phong lobe or a microfacet NDF.
void setSpecularModel(SpecularModel model, StandardMaterial& s) {
    s.phong = model == SpecularModel::Phong;
    s.microfacet.ndf = model == SpecularModel::Beckmann ? NdfKind::Beckmann : NdfKind::Ggx;
}

// The parameters of the specular interface that `standard` and a `layered` interface share,
// after its lobe model: roughness, the microfacet switches, the Fresnel model with F82 and the
// multiple-scattering compensation.
void readInterface(const JsonReader& r, StandardMaterial& s) {
    readRoughness(r, 0.5, s.microfacet);
    readMicrofacetSwitches(r, s.microfacet, true);
    s.fresnel = readFresnel(r, FresnelChoice::SchlickShadowed, false);
    if (r.has("f82") && r.has("f82_tint")) r.fail("give only one of f82 and f82_tint");
    if (const auto c = r.optionalTriple("f82", Range::unit())) s.f82 = toRgb(*c);
    if (const auto c = r.optionalTriple("f82_tint", Range::nonNegative())) s.f82Tint = toRgb(*c);
    if ((s.f82 || s.f82Tint) && s.fresnel != FresnelChoice::F82)
        r.fail("f82 / f82_tint need \"fresnel\": \"f82\"");
    s.microfacet.multiscatter = r.boolean("multiscatter", false);
    if (s.phong && s.microfacet.multiscatter)
        r.failAt("multiscatter", "compensates microfacet lobes only, not \"phong\"");
}

// The article sums Frostbite's renormalised diffuse and the specular lobe.
LayerCoupling readCoupling(const JsonReader& r, const StandardMaterial& s) {
    const LayerCoupling defaultCoupling =
        s.diffuse == DiffuseModel::Frostbite ? LayerCoupling::Sum : LayerCoupling::Fresnel;
    return r.choice("coupling", defaultCoupling, kLayerCouplingNames);
}

// The base of `layered`: a diffuse model (`type` one of kDiffuseModelNames, lambert by default)
// or a rough conductor (`type` "conductor" with the keys of the conductor material).
void readBase(const JsonReader& b, StandardMaterial& s) {
    std::vector<std::string> types = kDiffuseModelNames.names();
    types.emplace_back("conductor");
    b.noteNames("type", types);
    const std::string type = b.string("type", "lambert");
    if (type == "conductor") {
        auto conductor = readConductor(b).as<ConductorMaterial>();
        const MicrofacetParams& m = conductor.microfacet;
        if (std::max(m.alphaX, m.alphaY) < kSmoothAlpha)
            b.fail(
                "a conductor base needs a roughness (alpha >= 0.001): a smooth one would be a "
                "second delta lobe under the interface, which the stack does not have");
        if (conductor.thinFilm)
            b.failAt("thin_film", "is not supported on the conductor base of a layered material");
        s.conductorBase = std::make_shared<const ConductorMaterial>(std::move(conductor));
        s.diffuse.reset();
        return;
    }
    const auto model = kDiffuseModelNames.find(type);
    if (!model) b.failAt("type", "expected one of " + knownNames(types) + ", got \"" + type + "\"");
    s.diffuse = *model;
    s.baseColor = readColor(b, "reflectance", 0.5);
    if (s.diffuse != DiffuseModel::Lambert) {
        MicrofacetParams m;
        readRoughness(b, 0.5, m);
        s.diffuseRoughness = m.perceptualRoughness();
    }
}

}  // namespace

MaterialModel readStandard(const JsonReader& r) {
    StandardMaterial s;
    s.baseColor = readColor(r, "base_color", 0.8);
    s.metalness = r.number("metalness", 0.0, Range::unit());
    s.transmission = r.number("transmission", 0.0, Range::unit());
    const auto ior = r.optionalNumber("ior", Range::positive());
    const auto specular = r.optionalNumber("specular", Range::unit());
    // One of ior and specular implies the other (F0 = ((ior - 1) / (ior + 1))^2); given
    // neither, F0 = 0.04 and ior = 1.5, which agree.
    if (specular) {
        s.specular = *specular;
        const double root = std::sqrt(std::min(*specular, 0.999999));
        s.ior = ior.value_or((1.0 + root) / (1.0 - root));
    } else if (ior) {
        s.ior = *ior;
        s.specular = sqr((*ior - 1.0) / (*ior + 1.0));
    }
    if (const auto c = r.optionalTriple("specular_color", Range::unit())) {
        s.specularColor = toRgb(*c);
        if (r.has("metalness"))
            r.failAt("specular_color",
                     "the specular workflow (specular_color) excludes metalness; give one");
    }
    s.diffuse =
        choiceOrNone<DiffuseModel>(r, "diffuse_model", DiffuseModel::Lambert, kDiffuseModelNames);
    const auto model =
        choiceOrNone<SpecularModel>(r, "specular_model", SpecularModel::Ggx, kSpecularModelNames);
    s.specularLobe = model.has_value();
    setSpecularModel(model.value_or(SpecularModel::Ggx), s);
    readInterface(r, s);
    if (s.fresnel == FresnelChoice::Exact && s.metalness > 0)
        r.failAt("fresnel",
                 "\"exact\" is the dielectric Fresnel of `ior`; a metal's exact Fresnel needs "
                 "n and k: use a \"conductor\" material");
    s.coupling = readCoupling(r, s);
    prepareEnergyTables(s);
    return s;
}

// `layered`: the stack spelled out, an interface over a base with a coupling, built as the
// equivalent `standard` material in the specular workflow (one implementation of the stack).
MaterialModel readLayered(const JsonReader& r) {
    StandardMaterial s;
    if (const auto i = r.optionalChild("interface")) {
        i->expectObject();
        setSpecularModel(i->choice("model", SpecularModel::Ggx, kSpecularModelNames), s);
        readInterface(*i, s);
        const auto ior = i->optionalNumber("ior", Range::positive());
        const auto f0 = i->optionalTriple("f0", Range::unit());
        if (ior) s.ior = *ior;
        const double f0FromIor = sqr((s.ior - 1.0) / (s.ior + 1.0));
        s.specularColor = f0 ? toRgb(*f0) : RgbInput(f0FromIor);
        if (s.fresnel == FresnelChoice::Exact && f0)
            i->failAt("f0", "\"exact\" Fresnel takes the interface's ior, not f0");
        i->finish();
    } else {
        s.specularLobe = false;
    }
    if (const auto b = r.optionalChild("base")) {
        b->expectObject();
        readBase(*b, s);
        b->finish();
    } else {
        s.diffuse.reset();
    }
    s.transmission = r.number("transmission", 0.0, Range::unit());
    if (s.conductorBase && s.transmission > 0)
        r.failAt("transmission", "a conductor base is opaque; transmission needs a diffuse base");
    s.coupling = readCoupling(r, s);
    if (!s.specularLobe && !s.diffuse && !s.conductorBase && s.transmission == 0)
        r.fail("a layered material needs an interface, a base or transmission");
    prepareEnergyTables(s);
    return s;
}

void prepareEnergyTables(StandardMaterial& s) {
    if (s.microfacet.multiscatter && s.specularLobe && !s.phong)
        s.microfacet.energyF1 = microfacetEnergyTable(s.microfacet);
    if (s.coupling != LayerCoupling::Albedo) return;
    // The interface alone (with its compensation, if any), from the same builder.
    StandardMaterial interfaceOnly = s;
    interfaceOnly.diffuse.reset();
    interfaceOnly.conductorBase.reset();
    interfaceOnly.transmission = 0;
    interfaceOnly.coupling = LayerCoupling::Fresnel;
    MaterialDesc desc{"standard", interfaceOnly};
    const auto bsdf = buildBxdf(desc, SpectrumContext<Rgb<double>>{});
    s.interfaceAlbedo = std::make_shared<const AlbedoTable>(
        AlbedoTable::compute([&](const Vec3<double>& wo, double u1, double u2, double uc) {
            const auto r = bsdf->sample(wo, uc, {u1, u2}, TransportMode::Radiance);
            return r ? r->weight.average() : 0.0;
        }));
}

// The registrations of these types (material_kind.h; listed in material_kinds.cpp).

namespace {

constexpr TexturableKey kStandardTextured[] = {{"base_color", TexturedParameter::Color},
                                               {"roughness", TexturedParameter::Roughness}};

void texturedStandard(MaterialModel& model, const TexturedValues& t) {
    auto& s = model.as<StandardMaterial>();
    if (t.color) s.baseColor = *t.color;
    if (t.roughness) s.microfacet.alphaX = s.microfacet.alphaY = *t.roughness * *t.roughness;
}

void standardSpectra(const MaterialModel& model, std::vector<std::string>& out) {
    const auto& s = model.as<StandardMaterial>();
    if (s.conductorBase && s.conductorBase->optics.spectrum)
        out.push_back(s.conductorBase->optics.spectrum->name() + " (n, k)");
}

// What the polarised mode makes of both (layered.h).
constexpr std::string_view kStackPolarisation =
    "polarising at its interface: the Fresnel amplitudes of its index on each microfacet (an "
    "F0-only Fresnel model: the dielectric of that F0), from either side; its base, the "
    "transmission through the interface and the energy compensation depolarise (a phong "
    "interface too)";

bool standardTransmits(const MaterialModel& model) {
    return model.as<StandardMaterial>().transmission > 0;
}

// Multiscatter's albedo table and the albedo coupling's are computed from the roughness once.
bool standardTabulatesRoughness(const MaterialModel& model) {
    const auto& s = model.as<StandardMaterial>();
    return s.microfacet.multiscatter || s.coupling == LayerCoupling::Albedo;
}

}  // namespace

extern const MaterialKind kStandardMaterial{.name = "standard",
                                            .listPosition = 10,
                                            .read = readStandard,
                                            .schema = R"json({
  "type": "object",
  "description": "A specular interface over a diffuse base with transmission (docs/bsdf.md).",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "standard"},
    "base_color": {"$ref": "#/$defs/textured_reflectance"},
    "metalness": {"type": "number", "minimum": 0, "maximum": 1},
    "transmission": {"type": "number", "minimum": 0, "maximum": 1},
    "ior": {"type": "number", "exclusiveMinimum": 0},
    "specular": {"type": "number", "minimum": 0, "maximum": 1},
    "specular_color": {"$ref": "#/$defs/unit_triple"},
    "diffuse_model": {"enum": ["lambert", "oren_nayar", "burley", "frostbite", "none"]},
    "specular_model": {"enum": ["ggx", "beckmann", "phong", "none"]},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
    "g2": {"$ref": "#/$defs/g2"},
    "sampling": {"$ref": "#/$defs/sampling"},
    "fresnel": {"$ref": "#/$defs/fresnel"},
    "f82": {"$ref": "#/$defs/unit_triple"},
    "f82_tint": {"$ref": "#/$defs/non_negative_triple"},
    "multiscatter": {"type": "boolean", "default": false},
    "coupling": {"$ref": "#/$defs/coupling"}
  },
  "examples": [
    {"type": "standard", "base_color": [0.8, 0.2, 0.1], "roughness": 0.3, "metalness": 0.5},
    {
      "type": "standard",
      "base_color": {"spectrum": [[360, 0.1], [830, 0.9]]},
      "alpha": 0.1,
      "anisotropy": 0.5,
      "ior": 1.6,
      "diffuse_model": "burley",
      "coupling": "albedo"
    },
    {
      "type": "standard",
      "specular_color": [0.04, 0.04, 0.04],
      "alpha_x": 0.1,
      "alpha_y": 0.3,
      "fresnel": "f82",
      "f82_tint": [1, 0.9, 0.8],
      "g2": "separable",
      "sampling": "walter",
      "multiscatter": true,
      "specular": 0.5,
      "specular_model": "beckmann",
      "transmission": 0.2
    }
  ]
})json",
                                            .texturable = kStandardTextured,
                                            .applyTextures = texturedStandard,
                                            .spectralData = standardSpectra,
                                            .polarisation = kStackPolarisation,
                                            .transmits = standardTransmits,
                                            .tabulatesRoughness = standardTabulatesRoughness};

extern const MaterialKind kLayeredMaterial{.name = "layered",
                                           .listPosition = 110,
                                           .read = readLayered,
                                           .schema = R"json({
  "type": "object",
  "description": "The stack spelled out: an interface over a base, with transmission and a coupling.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "layered"},
    "interface": {
      "type": "object",
      "additionalProperties": false,
      "properties": {
        "model": {"$ref": "#/$defs/specular_model"},
        "roughness": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
        "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
        "g2": {"$ref": "#/$defs/g2"},
        "sampling": {"$ref": "#/$defs/sampling"},
        "fresnel": {"$ref": "#/$defs/fresnel"},
        "f82": {"$ref": "#/$defs/unit_triple"},
        "f82_tint": {"$ref": "#/$defs/non_negative_triple"},
        "multiscatter": {"type": "boolean", "default": false},
        "ior": {"type": "number", "exclusiveMinimum": 0},
        "f0": {"$ref": "#/$defs/unit_triple"}
      }
    },
    "base": {
      "type": "object",
      "additionalProperties": false,
      "properties": {
        "type": {"$ref": "#/$defs/layered_base_type"},
        "reflectance": {"$ref": "#/$defs/reflectance"},
        "roughness": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
        "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
        "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
        "material": {"type": "string"},
        "eta": {"$ref": "#/$defs/conductor_eta"},
        "k": {"$ref": "#/$defs/conductor_k"},
        "nk_file": {"type": "string"},
        "f0": {"$ref": "#/$defs/unit_triple"},
        "f82": {"$ref": "#/$defs/unit_triple"},
        "distribution": {"enum": ["ggx", "beckmann", "blinn_phong"]},
        "g2": {"$ref": "#/$defs/g2"},
        "sampling": {"$ref": "#/$defs/sampling"},
        "fresnel": {"enum": ["schlick", "schlick_shadowed", "schlick_sg", "f82", "exact", "auto"]},
        "multiscatter": {"type": "boolean", "default": false},
        "thin_film": false
      }
    },
    "transmission": {"type": "number", "minimum": 0, "maximum": 1},
    "coupling": {"$ref": "#/$defs/coupling"}
  },
  "examples": [
    {
      "type": "layered",
      "interface": {"model": "ggx", "roughness": 0.2, "ior": 1.5},
      "base": {"type": "lambert", "reflectance": [0.7, 0.2, 0.2]},
      "coupling": "albedo"
    },
    {
      "type": "layered",
      "interface": {
        "model": "beckmann",
        "alpha": 0.1,
        "f0": 0.04,
        "fresnel": "f82",
        "f82": 0.9,
        "g2": "separable",
        "sampling": "vndf",
        "multiscatter": true
      },
      "base": {"type": "oren_nayar", "reflectance": 0.5, "roughness": 0.5},
      "transmission": 0.1
    },
    {
      "type": "layered",
      "interface": {"alpha_x": 0.1, "alpha_y": 0.2, "fresnel": "f82", "f82_tint": [1, 1, 1]}
    },
    {"type": "layered", "interface": {"anisotropy": 0.5}, "base": {"type": "burley", "alpha": 0.3}},
    {"type": "layered", "base": {"type": "frostbite", "alpha_x": 0.2, "alpha_y": 0.2}},
    {
      "type": "layered",
      "interface": {"roughness": 0.15, "ior": 1.5, "fresnel": "exact"},
      "base": {"type": "conductor", "material": "Au", "roughness": 0.3},
      "coupling": "albedo"
    },
    {
      "type": "layered",
      "interface": {"alpha": 0.02, "ior": 1.4},
      "base": {
        "type": "conductor",
        "eta": [0.2, 0.9, 1.1],
        "k": [3.9, 2.4, 2.2],
        "alpha_x": 0.1,
        "alpha_y": 0.3,
        "distribution": "beckmann",
        "g2": "separable",
        "sampling": "walter",
        "fresnel": "exact",
        "multiscatter": true
      }
    }
  ]
})json",
                                           .spectralData = standardSpectra,
                                           .polarisation = kStackPolarisation,
                                           .transmits = standardTransmits,
                                           .tabulatesRoughness = standardTabulatesRoughness};

}  // namespace lamina
