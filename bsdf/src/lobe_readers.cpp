// Materials of one lobe: the diffuse models (`lambert`, `oren_nayar`, `burley`, `frostbite`),
// `diffuse_transmission` and the article's `phong` (docs/bsdf.md, "Materials").
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/diffuse_transmission.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/phong.h"
#include "material_readers.h"

namespace lamina {

MaterialModel readDiffuse(const JsonReader& r, DiffuseModel model) {
    DiffuseMaterial d;
    d.model = model;
    d.reflectance = readColor(r, "reflectance", 0.5);
    if (model != DiffuseModel::Lambert) {
        MicrofacetParams m;
        readRoughness(r, 0.5, m);
        if (m.alphaX != m.alphaY) r.fail("diffuse roughness is isotropic");
        d.roughness = m.perceptualRoughness();
    }
    return d;
}

MaterialModel readDiffuseTransmission(const JsonReader& r) {
    DiffuseTransmissionMaterial d;
    d.reflectance = readColor(r, "reflectance", 0.25);
    d.transmittance = readColor(r, "transmittance", 0.25);
    return d;
}

MaterialModel readPhong(const JsonReader& r) {
    PhongMaterial p;
    p.reflectance = readColor(r, "reflectance", 0.5);
    if (r.has("shininess")) {
        if (r.has("roughness") || r.has("alpha"))
            r.fail("give either shininess or a roughness (roughness or alpha), not both");
        p.shininess = r.requiredNumber("shininess", {0.0, 1e6});
    } else {
        MicrofacetParams m;
        readRoughness(r, 0.5, m);
        if (m.alphaX != m.alphaY) r.fail("the Phong lobe is isotropic");
        p.shininess = PhongLobe<Rgb<double>>::shininessFromAlpha(m.alphaX);
    }
    return p;
}

// The registrations of these types (material_kind.h; listed in material_kinds.cpp).

namespace {

constexpr TexturableKey kLambertTextured[] = {{"reflectance", TexturedParameter::Color}};
constexpr TexturableKey kRoughDiffuseTextured[] = {{"reflectance", TexturedParameter::Color},
                                                   {"roughness", TexturedParameter::Roughness}};
constexpr TexturableKey kPhongTextured[] = {{"reflectance", TexturedParameter::Color},
                                            {"roughness", TexturedParameter::Roughness}};

void texturedDiffuse(MaterialModel& model, const TexturedValues& t) {
    auto& d = model.as<DiffuseMaterial>();
    if (t.color) d.reflectance = *t.color;
    if (t.roughness) d.roughness = *t.roughness;
}

void texturedDiffuseTransmission(MaterialModel& model, const TexturedValues& t) {
    if (t.color) model.as<DiffuseTransmissionMaterial>().reflectance = *t.color;
}

void texturedPhong(MaterialModel& model, const TexturedValues& t) {
    auto& p = model.as<PhongMaterial>();
    if (t.color) p.reflectance = *t.color;
    // The roughness as readPhong takes it: alpha = roughness^2, then Walter's shininess.
    if (t.roughness)
        p.shininess = PhongLobe<Rgb<double>>::shininessFromAlpha(*t.roughness * *t.roughness);
}

}  // namespace

extern const MaterialKind kLambertMaterial{.name = kDiffuseModelNames.name(DiffuseModel::Lambert),
                                           .listPosition = 20,
                                           .read = readDiffuseModel<DiffuseModel::Lambert>,
                                           .schema = R"json({
  "type": "object",
  "description": "A diffuse lobe alone: lambert.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "lambert"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"}
  },
  "examples": [{"type": "lambert", "reflectance": [0.5, 0.5, 0.5]}]
})json",
                                           .texturable = kLambertTextured,
                                           .applyTextures = texturedDiffuse};

extern const MaterialKind kOrenNayarMaterial{
    .name = kDiffuseModelNames.name(DiffuseModel::OrenNayar),
    .listPosition = 30,
    .read = readDiffuseModel<DiffuseModel::OrenNayar>,
    .schema = R"json({
  "type": "object",
  "description": "A diffuse lobe alone: oren_nayar.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "oren_nayar"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0}
  },
  "examples": [{"type": "oren_nayar", "reflectance": 0.5, "roughness": 0.4}]
})json",
    .texturable = kRoughDiffuseTextured,
    .applyTextures = texturedDiffuse};

extern const MaterialKind kBurleyMaterial{.name = kDiffuseModelNames.name(DiffuseModel::Burley),
                                          .listPosition = 40,
                                          .read = readDiffuseModel<DiffuseModel::Burley>,
                                          .schema = R"json({
  "type": "object",
  "description": "A diffuse lobe alone: burley.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "burley"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0}
  },
  "examples": [{"type": "burley", "reflectance": 0.5, "roughness": 0.4}]
})json",
                                          .texturable = kRoughDiffuseTextured,
                                          .applyTextures = texturedDiffuse};

extern const MaterialKind kFrostbiteMaterial{
    .name = kDiffuseModelNames.name(DiffuseModel::Frostbite),
    .listPosition = 50,
    .read = readDiffuseModel<DiffuseModel::Frostbite>,
    .schema = R"json({
  "type": "object",
  "description": "A diffuse lobe alone: frostbite.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "frostbite"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0}
  },
  "examples": [{"type": "frostbite", "reflectance": 0.5, "roughness": 0.4}]
})json",
    .texturable = kRoughDiffuseTextured,
    .applyTextures = texturedDiffuse};

namespace {
constexpr TexturableKey kDiffuseTransmissionTextured[] = {
    {"reflectance", TexturedParameter::Color}};
}  // namespace

extern const MaterialKind kDiffuseTransmissionMaterial{
    .name = "diffuse_transmission",
    .listPosition = 70,
    .read = readDiffuseTransmission,
    .schema = R"json({
  "type": "object",
  "description": "Lambertian reflection on the side of the incoming direction plus Lambertian transmission to the other (pbrt-v4's DiffuseTransmissionBxDF); a texture applies to reflectance only.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "diffuse_transmission"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"},
    "transmittance": {"$ref": "#/$defs/reflectance"}
  },
  "examples": [
    {"type": "diffuse_transmission", "reflectance": 0.25, "transmittance": 0.25},
    {
      "type": "diffuse_transmission",
      "reflectance": [0.3, 0.5, 0.2],
      "transmittance": {"spectrum": [[360, 0.1], [830, 0.6]]}
    }
  ]
})json",
    .texturable = kDiffuseTransmissionTextured,
    .applyTextures = texturedDiffuseTransmission,
    .transmits = [](const MaterialModel& m) {
        const auto& t = m.as<DiffuseTransmissionMaterial>().transmittance;
        return t.rgb.maxValue() > 0 || t.spectrum != nullptr;
    }};

extern const MaterialKind kPhongMaterial{.name = "phong",
                                         .listPosition = 100,
                                         .read = readPhong,
                                         .schema = R"json({
  "type": "object",
  "description": "The article's Phong lobe: shininess, or a roughness converted to it.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "phong"},
    "reflectance": {"$ref": "#/$defs/textured_reflectance"},
    "shininess": {"type": "number", "minimum": 0, "maximum": 1000000.0},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0}
  },
  "examples": [
    {"type": "phong", "reflectance": 0.5, "shininess": 50},
    {"type": "phong", "reflectance": [0.4, 0.5, 0.6], "alpha": 0.2}
  ]
})json",
                                         .texturable = kPhongTextured,
                                         .applyTextures = texturedPhong};

}  // namespace lamina
