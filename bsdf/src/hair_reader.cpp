// The `hair` material (hair.h, docs/bsdf.md "Hair"): its reader and registration. The fibre's
// absorption is given one of three ways, pbrt-v4's: `sigma_a` itself, else the `reflectance`
// the fibres should have (Chiang et al. 2016's inverse), else the melanin concentrations.
#include "lamina/bsdf/hair.h"
#include "lamina/bsdf/material_kind.h"
#include "material_readers.h"

namespace lamina {

namespace {

MaterialModel readHair(const JsonReader& r) {
    HairMaterial h;
    h.eta = r.number("eta", 1.55, {1.0, 5.0});
    h.betaM = r.number("beta_m", 0.3, Range::unit());
    h.betaN = r.number("beta_n", 0.3, Range::unit());
    h.alphaDegrees = r.number("alpha", 2.0, {-30.0, 30.0});
    const int given = int(r.has("sigma_a")) + int(r.has("reflectance")) +
                      int(r.has("eumelanin") || r.has("pheomelanin"));
    if (given > 1)
        r.fail("give the absorption one way: sigma_a, reflectance, or eumelanin and pheomelanin");
    if (r.has("sigma_a")) {
        h.sigmaA = toRgb(r.requiredArray<3>("sigma_a", {0.0, 1e4}));
    } else if (r.has("reflectance")) {
        h.sigmaA = hairAbsorptionFromColor(readColor(r, "reflectance", 0.5).rgb, h.betaN);
    } else {
        // Brown (eumelanin 1.3) when nothing is given; a concentration left out is 0.
        const bool none = !r.has("eumelanin") && !r.has("pheomelanin");
        h.sigmaA = hairAbsorptionFromMelanin(r.number("eumelanin", none ? 1.3 : 0.0, {0.0, 100.0}),
                                             r.number("pheomelanin", 0.0, {0.0, 100.0}));
    }
    return h;
}

}  // namespace

extern const MaterialKind kHairMaterial{.name = "hair",
                                        .listPosition = 170,
                                        .read = readHair,
                                        .schema = R"json({
  "type": "object",
  "description": "Chiang et al. 2016's hair fibre (d'Eon et al. 2011's longitudinal lobes), for curves: the shading frame's x axis runs along the fibre. The absorption is sigma_a, or the reflectance the fibres should have, or melanin concentrations (the default: eumelanin 1.3).",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "hair"},
    "sigma_a": {"$ref": "#/$defs/vec3", "description": "absorption per unit fibre radius, linear Rec.709"},
    "reflectance": {"$ref": "#/$defs/reflectance", "description": "the colour the fibres should have: sigma_a by Chiang et al.'s inverse"},
    "eumelanin": {"type": "number", "minimum": 0, "maximum": 100, "default": 1.3},
    "pheomelanin": {"type": "number", "minimum": 0, "maximum": 100, "default": 0},
    "eta": {"type": "number", "minimum": 1, "maximum": 5, "default": 1.55},
    "beta_m": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.3, "description": "longitudinal roughness"},
    "beta_n": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.3, "description": "azimuthal roughness"},
    "alpha": {"type": "number", "minimum": -30, "maximum": 30, "default": 2, "description": "cuticle scale tilt, degrees"}
  },
  "examples": [{"type": "hair", "eumelanin": 1.3}, {"type": "hair", "reflectance": [0.6, 0.4, 0.2]}]
})json",
                                        .transmits = [](const MaterialModel&) { return true; }};

}  // namespace lamina
