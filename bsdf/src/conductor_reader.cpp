// `conductor`: a metal's optics in one of four forms, a microfacet NDF and a Fresnel model
// (docs/bsdf.md, "Materials").
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

bool ConductorOptics::etaKIsGrey() const {
    return eta[0] == eta[1] && eta[1] == eta[2] && k[0] == k[1] && k[1] == k[2];
}

}  // namespace lamina
