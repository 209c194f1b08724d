// `conductor`: a metal's optics in one of four forms, a microfacet NDF and a Fresnel model
// (docs/bsdf.md, "Materials").
#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/material_kind.h"
#include "material_readers.h"

namespace lamina {

namespace {

// A spectrum given inline: [[nm, value], ...] with increasing wavelengths.
bool isSpectrum(const JsonReader& r, const std::string& key) {
    if (!r.has(key)) return false;
    const Json& v = r.value()[key];
    return v.is_array() && !v.empty() && v[0].is_array();
}

IorSpectrum::Curve readSpectrumCurve(const JsonReader& r, Range range) {
    auto [nm, values] = r.wavelengthTable(range);
    return tabulatedCurve(std::move(nm), std::move(values), r.source().name + ": " + r.path());
}

ConductorOptics readOptics(const JsonReader& r) {
    ConductorOptics o;
    const bool etaK = r.has("eta") || r.has("k");
    const bool f0 = r.has("f0") || r.has("f82");
    const bool named = r.has("material"), file = r.has("nk_file");
    if (int(etaK) + int(f0) + int(named) + int(file) != 1)
        r.fail(
            "a conductor's optics are exactly one of {\"material\": name}, {\"eta\", \"k\"}, "
            "{\"nk_file\": path} or {\"f0\", \"f82\"}");
    if (named || file) {
        if (named) {
            const std::string name = r.requiredString("material");
            const auto ior = namedIor(name);
            if (!ior || ior->k(550) == 0)
                r.failAt("material", "unknown metal \"" + name + "\"; expected one of " +
                                         knownNames(namedMetalNames()));
            return ConductorOptics::fromSpectrum(std::make_shared<const IorSpectrum>(*ior));
        }
        return ConductorOptics::fromSpectrum(loadIorAt(r, "nk_file"));
    } else if (etaK && (isSpectrum(r, "eta") || isSpectrum(r, "k"))) {
        // eta and k as spectra: lists of [nm, value] (a number is a constant spectrum).
        if (!r.has("eta") || !r.has("k")) r.fail("give both eta and k");
        auto curve = [&](const std::string& key, Range range) -> IorSpectrum::Curve {
            if (!isSpectrum(r, key)) {
                const double v = r.number(key, 0.0, range);
                if (!r.value()[key].is_number())
                    r.failAt(key, "with a spectrum for the other, expected a number or a spectrum");
                return [v](double) { return v; };
            }
            return readSpectrumCurve(r.child(key), range);
        };
        const auto eta = curve("eta", Range::positive());
        const auto k = curve("k", Range::nonNegative());
        return ConductorOptics::fromSpectrum(std::make_shared<const IorSpectrum>(
            r.path().empty() ? "eta/k" : r.path(), eta, k, true));
    } else if (etaK) {
        o.form = ConductorOptics::Form::EtaK;
        o.eta = toRgb(r.optionalTriple("eta", Range::positive()).value_or(std::array<double, 3>{}));
        if (!r.has("eta")) r.failAt("eta", "missing; expected a number > 0 or [r, g, b]");
        if (!r.has("k")) r.failAt("k", "missing; expected a number >= 0 or [r, g, b]");
        o.k = toRgb(*r.optionalTriple("k", Range::nonNegative()));
    } else {
        o.form = ConductorOptics::Form::F0F82;
        if (!r.has("f0")) r.failAt("f0", "missing; expected a number in [0, 1] or [r, g, b]");
        o.f0 = toRgb(*r.optionalTriple("f0", Range::unit()));
        if (const auto v = r.optionalTriple("f82", Range::unit())) o.f82 = toRgb(*v);
    }
    return o;
}

}  // namespace

MaterialModel readConductor(const JsonReader& r) {
    ConductorMaterial c;
    c.optics = readOptics(r);
    c.microfacet.ndf = r.choice("distribution", NdfKind::Ggx, kNdfKindNames);
    readRoughness(r, 0.0, c.microfacet);
    readMicrofacetSwitches(r, c.microfacet, true);
    c.fresnel = readFresnel(r, FresnelChoice::Auto, true);
    c.microfacet.multiscatter = r.boolean("multiscatter", false);
    prepareEnergyTables(c);
    if (c.optics.form == ConductorOptics::Form::F0F82 && c.fresnel == FresnelChoice::Exact)
        r.failAt("fresnel", "\"exact\" needs the eta and k of the conductor, not f0");
    c.thinFilm = readThinFilm(r);
    if (c.thinFilm && c.optics.form == ConductorOptics::Form::F0F82)
        r.failAt("thin_film",
                 "needs the conductor's n and k (material, eta and k, or nk_file), "
                 "not f0 and f82");
    if (c.thinFilm && c.fresnel != FresnelChoice::Auto && c.fresnel != FresnelChoice::Exact)
        r.failAt("thin_film",
                 "needs the exact Fresnel equations; expected fresnel \"exact\" or "
                 "\"auto\", got \"" +
                     std::string(kFresnelChoiceNames.name(c.fresnel)) + "\"");
    return c;
}

void prepareEnergyTables(ConductorMaterial& c) {
    if (c.microfacet.multiscatter) c.microfacet.energyF1 = microfacetEnergyTable(c.microfacet);
}

ConductorOptics ConductorOptics::fromSpectrum(std::shared_ptr<const IorSpectrum> spectrum) {
    ConductorOptics o;
    o.form = Form::Spectral;
    o.table = std::make_shared<const NkTable>(spectrum);
    std::tie(o.f0, o.f82) = conductorF0F82(*spectrum);
    o.spectrum = std::move(spectrum);
    return o;
}

// The registrations of these types (material_kind.h; listed in material_kinds.cpp).

namespace {

constexpr TexturableKey kConductorTextured[] = {{"roughness", TexturedParameter::Roughness}};

void texturedConductor(MaterialModel& model, const TexturedValues& t) {
    auto& c = model.as<ConductorMaterial>();
    if (t.roughness) c.microfacet.alphaX = c.microfacet.alphaY = *t.roughness * *t.roughness;
}

void conductorSpectra(const MaterialModel& model, std::vector<std::string>& out) {
    const auto& c = model.as<ConductorMaterial>();
    if (c.optics.spectrum) out.push_back(c.optics.spectrum->name() + " (n, k)");
    describeThinFilm(c.thinFilm, out);
}

}  // namespace

extern const MaterialKind kConductorMaterial{
    .name = "conductor",
    .listPosition = 60,
    .read = readConductor,
    .schema = R"json({
  "type": "object",
  "description": "A metal: named, eta and k (numbers, [r, g, b] or spectra), an n/k file, or f0 and f82.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "conductor"},
    "material": {"type": "string"},
    "eta": {"$ref": "#/$defs/conductor_eta"},
    "k": {"$ref": "#/$defs/conductor_k"},
    "nk_file": {"type": "string"},
    "f0": {"$ref": "#/$defs/unit_triple"},
    "f82": {"$ref": "#/$defs/unit_triple"},
    "distribution": {"enum": ["ggx", "beckmann", "blinn_phong"]},
    "roughness": {"$ref": "#/$defs/textured_roughness"},
    "alpha": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_x": {"type": "number", "minimum": 0, "maximum": 1},
    "alpha_y": {"type": "number", "minimum": 0, "maximum": 1},
    "anisotropy": {"type": "number", "minimum": 0, "maximum": 0.99, "default": 0},
    "g2": {"$ref": "#/$defs/g2"},
    "sampling": {"$ref": "#/$defs/sampling"},
    "fresnel": {"enum": ["schlick", "schlick_shadowed", "schlick_sg", "f82", "exact", "auto"]},
    "multiscatter": {"type": "boolean", "default": false},
    "thin_film": {"$ref": "#/$defs/thin_film"}
  },
  "examples": [
    {"type": "conductor", "material": "Au", "roughness": 0.2, "multiscatter": true},
    {"type": "conductor", "material": "Ti", "roughness": 0.1, "thin_film": {"thickness_nm": 250, "ior": 2.4}},
    {
      "type": "conductor",
      "eta": [0.2, 0.9, 1.1],
      "k": [3.9, 2.4, 2.2],
      "alpha": 0.05,
      "distribution": "beckmann",
      "fresnel": "exact"
    },
    {
      "type": "conductor",
      "k": [[360, 2.0], [830, 4.0]],
      "eta": 1.2,
      "alpha_x": 0.1,
      "alpha_y": 0.2
    },
    {
      "type": "conductor",
      "f0": [0.9, 0.6, 0.3],
      "f82": 0.8,
      "fresnel": "f82",
      "g2": "separable",
      "sampling": "vndf"
    }
  ]
})json",
    .texturable = kConductorTextured,
    .applyTextures = texturedConductor,
    .spectralData = conductorSpectra,
    .polarisation =
        "polarising: the Fresnel amplitudes of its optics "
        "on each microfacet (its multiple-scattering "
        "compensation depolarises)",
    .tabulatesRoughness = [](const MaterialModel& m) {
        return m.as<ConductorMaterial>().microfacet.multiscatter;
    }};

}  // namespace lamina
