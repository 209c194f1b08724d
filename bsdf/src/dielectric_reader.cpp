// `dielectric`: the index of refraction as a number, a named glass, a file or a dispersion
// formula (spectral/ior_spectrum.h), and a microfacet NDF; `thin_dielectric`: the same index
// (docs/bsdf.md, "Materials").
#include <cmath>
#include <tuple>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/thin_dielectric.h"
#include "lamina/spectral/cie.h"
#include "material_readers.h"

namespace lamina {

namespace {

// The NDFs of a rough dielectric: those with a visible-normal sampler, which its sampling uses.
constexpr auto kDielectricNdfNames =
    kNdfKindNames.subset(std::array{NdfKind::Ggx, NdfKind::Beckmann});

// {"cauchy": [A, B]} or [A, B, C], wavelength in um.
IorSpectrum readCauchy(const JsonReader& f) {
    const Json& c = f.value()["cauchy"];
    if (!c.is_array() || c.size() < 2 || c.size() > 3)
        f.failAt("cauchy", "expected [A, B] or [A, B, C] (wavelength in um)");
    std::array<double, 3> k{0, 0, 0};
    for (std::size_t i = 0; i < c.size(); ++i)
        k[i] = f.checkNumber(c[i], f.childPath("cauchy") + "[" + std::to_string(i) + "]",
                             i == 0 ? Range::positive() : Range::any());
    (void)f.child("cauchy");
    return cauchyIor(k[0], k[1], k[2]);
}

// {"sellmeier": {"b": [...], "c": [...]}}, c in um^2.
IorSpectrum readSellmeier(const JsonReader& f) {
    const JsonReader sm = f.child("sellmeier");
    const Json& b = sm.value()["b"];
    const Json& c = sm.value()["c"];
    if (!sm.has("b") || !sm.has("c") || !b.is_array() || !c.is_array() || b.size() != c.size() ||
        b.empty())
        sm.fail("expected {\"b\": [...], \"c\": [...]} of equal, non-zero length (c in um^2)");
    std::vector<double> bs, cs;
    for (std::size_t i = 0; i < b.size(); ++i) {
        bs.push_back(
            sm.checkNumber(b[i], sm.childPath("b") + "[" + std::to_string(i) + "]", Range::any()));
        cs.push_back(sm.checkNumber(c[i], sm.childPath("c") + "[" + std::to_string(i) + "]",
                                    Range::nonNegative()));
    }
    // n^2 = 1 + sum B lambda^2 / (lambda^2 - C) has a pole at lambda = sqrt(C) um: inside
    // the rendered wavelengths it gives an infinite index, and beyond it a negative n^2.
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const double poleNm = 1e3 * std::sqrt(cs[i]);
        if (bs[i] != 0 && poleNm >= kLambdaMin && poleNm <= kLambdaMax)
            sm.failAt("c[" + std::to_string(i) + "]",
                      "puts a pole of the formula at " + formatNumber(poleNm) +
                          " nm, inside the rendered range " + formatNumber(kLambdaMin) + "-" +
                          formatNumber(kLambdaMax) + " nm");
    }
    (void)sm.child("b");
    (void)sm.child("c");
    sm.finish();
    return sellmeierIor(bs, cs);
}

// {"cauchy": ...} or {"sellmeier": ...}: exactly one dispersion formula.
IorSpectrum readDispersionFormula(const JsonReader& f) {
    if (f.has("cauchy") == f.has("sellmeier"))
        f.fail("expected exactly one of cauchy and sellmeier");
    IorSpectrum ior = f.has("cauchy") ? readCauchy(f) : readSellmeier(f);
    // Whatever the coefficients, the index must be a positive float at every wavelength that
    // is rendered (1 nm steps find a negative or overflowing stretch of either formula).
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 1.0) {
        const double n = ior.n(nm);
        if (!(n > 0) || !std::isfinite(float(n)))
            f.fail("the formula gives n = " + formatNumber(n) + " at " + formatNumber(nm) +
                   " nm; expected a positive index over " + formatNumber(kLambdaMin) + "-" +
                   formatNumber(kLambdaMax) + " nm");
    }
    f.finish();
    return ior;
}

}  // namespace

std::pair<double, std::shared_ptr<const IorSpectrum>> readDielectricIor(const JsonReader& r) {
    std::shared_ptr<const IorSpectrum> spectrum;
    if (r.has("ior") && r.has("ior_file")) r.fail("give only one of ior and ior_file");
    if (r.has("ior_file")) {
        spectrum = loadIorAt(r, "ior_file");
    } else if (r.has("ior") && r.value()["ior"].is_object()) {
        spectrum = std::make_shared<const IorSpectrum>(readDispersionFormula(r.child("ior")));
    } else if (r.has("ior") && r.value()["ior"].is_string()) {
        const std::string name = r.requiredString("ior");
        const auto ior = namedIor(name);
        if (!ior || ior->k(550) != 0)
            r.failAt("ior", "unknown glass \"" + name + "\"; expected a number or one of " +
                                knownNames(namedGlassNames()));
        spectrum = std::make_shared<const IorSpectrum>(*ior);
    } else {
        return {r.number("ior", 1.5, Range::positive()), nullptr};
    }
    const double ior = spectrum->n(kDLineNm);
    if (!(ior > 0)) r.fail("the index of refraction at 587.56 nm is not positive");
    return {ior, std::move(spectrum)};
}

MaterialModel readDielectric(const JsonReader& r) {
    DielectricMaterial d;
    std::tie(d.ior, d.spectrum) = readDielectricIor(r);
    d.microfacet.ndf = r.choice("distribution", NdfKind::Ggx, kDielectricNdfNames);
    readRoughness(r, 0.0, d.microfacet);
    readMicrofacetSwitches(r, d.microfacet, false);
    d.thinFilm = readThinFilm(r);
    return d;
}

MaterialModel readThinDielectric(const JsonReader& r) {
    ThinDielectricMaterial t;
    std::tie(t.ior, t.spectrum) = readDielectricIor(r);
    return t;
}

// The registrations of these types (material_kind.h; listed in material_kinds.cpp).

namespace {

constexpr TexturableKey kDielectricTextured[] = {{"roughness", TexturedParameter::Roughness}};

void texturedDielectric(MaterialModel& model, const TexturedValues& t) {
    auto& d = model.as<DielectricMaterial>();
    if (t.roughness) d.microfacet.alphaX = d.microfacet.alphaY = *t.roughness * *t.roughness;
}

void dielectricSpectra(const MaterialModel& model, std::vector<std::string>& out) {
    const auto& d = model.as<DielectricMaterial>();
    if (d.spectrum) out.push_back(d.spectrum->name() + " (dispersion)");
    describeThinFilm(d.thinFilm, out);
}

void thinDielectricSpectra(const MaterialModel& model, std::vector<std::string>& out) {
    const auto& t = model.as<ThinDielectricMaterial>();
    if (t.spectrum) out.push_back(t.spectrum->name() + " (index per wavelength)");
}

}  // namespace

extern const MaterialKind kDielectricMaterial{
    .name = "dielectric",
    .listPosition = 80,
    .read = readDielectric,
    .schema = R"json({
  "type": "object",
  "description": "Glass: ior as a number, a named glass or a dispersion formula, or an index file.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "dielectric"},
    "ior": {
      "oneOf": [
        {"type": "number", "exclusiveMinimum": 0},
        {"type": "string"},
        {"$ref": "#/$defs/dispersion_formula"}
      ]
    },
    "ior_file": {"type": "string"},
    "distribution": {"enum": ["ggx", "beckmann"]},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
    "g2": {"$ref": "#/$defs/g2"},
    "thin_film": {"$ref": "#/$defs/thin_film"}
  },
  "examples": [
    {"type": "dielectric", "ior": 1.5, "roughness": 0.1},
    {"type": "dielectric", "ior": 1.0, "thin_film": {"thickness_nm": 400, "ior": 1.33}},
    {"type": "dielectric", "ior": "bk7"},
    {
      "type": "dielectric",
      "ior": {
        "sellmeier": {
          "b": [1.03961212, 0.231792344, 1.01046945],
          "c": [0.00600069867, 0.0200179144, 103.560653]
        }
      },
      "distribution": "beckmann",
      "alpha": 0.05,
      "g2": "separable"
    },
    {"type": "dielectric", "ior": {"cauchy": [1.5046, 0.0042]}}
  ]
})json",
    .texturable = kDielectricTextured,
    .applyTextures = texturedDielectric,
    .spectralData = dielectricSpectra,
    .polarisation =
        "polarising: the Fresnel amplitudes on each "
        "microfacet, with the phase of total internal "
        "reflection",
    .transmits = [](const MaterialModel&) { return true; }};

extern const MaterialKind kThinDielectricMaterial{
    .name = "thin_dielectric",
    .listPosition = 90,
    .read = readThinDielectric,
    .schema = R"json({
  "type": "object",
  "description": "A thin slab of glass (pbrt-v4's ThinDielectricBxDF): mirror reflection and straight transmission with the slab's inter-reflections; ior as dielectric takes it.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "thin_dielectric"},
    "ior": {
      "oneOf": [
        {"type": "number", "exclusiveMinimum": 0},
        {"type": "string"},
        {"$ref": "#/$defs/dispersion_formula"}
      ]
    },
    "ior_file": {"type": "string"}
  },
  "examples": [
    {"type": "thin_dielectric", "ior": 1.5},
    {"type": "thin_dielectric", "ior": "bk7"},
    {"type": "thin_dielectric", "ior": {"cauchy": [1.5046, 0.0042]}}
  ]
})json",
    .spectralData = thinDielectricSpectra,
    .polarisation =
        "polarising: the slab's internal reflections summed for s and p apart (a one-plate "
        "pile-of-plates polariser)",
    .transmits = [](const MaterialModel&) { return true; }};

}  // namespace lamina
