// JSON -> MaterialDesc, with validation (docs/bsdf.md, "Materials").
#include <cmath>
#include <fstream>
#include <sstream>

#include "lamina/bsdf/material_builder.h"

namespace lamina {

namespace {

constexpr const char* kTypeNames[] = {"standard",  "lambert",   "oren_nayar", "burley",
                                      "frostbite", "conductor", "dielectric", "phong",
                                      "layered",   "mix",       nullptr};

RgbInput toRgb(const std::array<double, 3>& a) {
    return RgbInput(a[0], a[1], a[2]);
}

// A colour: a number, [r, g, b], or {"spectrum": [[nm, reflectance], ...]} (a measured
// reflectance; RGB mode uses its colour under D65).
ColorInput readColor(const JsonReader& r, const std::string& key, double defaultValue) {
    if (!r.has(key) || !r.value()[key].is_object())
        return toRgb(r.triple(key, {defaultValue, defaultValue, defaultValue}, Range::unit()));
    const JsonReader c = r.child(key);
    const JsonReader list = c.child("spectrum");
    auto [nm, values] = list.wavelengthTable(Range::unit());
    c.finish();
    ColorInput out;
    out.spectrum = std::make_shared<const std::function<double(double)>>(
        tabulatedCurve(std::move(nm), std::move(values), r.source().name + ": " + list.path()));
    out.rgb = reflectanceColor(*out.spectrum);
    return out;
}

// Roughness in one of three forms: perceptual `roughness` (alpha = roughness^2), `alpha`, or
// `alpha_x` and `alpha_y`; `anisotropy` in [0, 1) stretches the first two along the tangent
// (Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks", slide 20:
// aspect = sqrt(1 - 0.9 anisotropy), alpha_x = alpha / aspect, alpha_y = alpha aspect).
void readRoughness(const JsonReader& r, double defaultRoughness, MicrofacetParams& m) {
    const int forms =
        int(r.has("roughness")) + int(r.has("alpha")) + int(r.has("alpha_x") || r.has("alpha_y"));
    if (forms > 1) r.fail("give only one of roughness, alpha, or alpha_x and alpha_y");
    if (r.has("alpha_x") || r.has("alpha_y")) {
        m.alphaX = r.requiredNumber("alpha_x", Range::unit());
        m.alphaY = r.requiredNumber("alpha_y", Range::unit());
        if (r.has("anisotropy")) r.failAt("anisotropy", "not allowed with alpha_x and alpha_y");
        return;
    }
    double alpha = sqr(defaultRoughness);
    if (r.has("alpha")) alpha = r.requiredNumber("alpha", Range::unit());
    if (r.has("roughness")) alpha = sqr(r.requiredNumber("roughness", Range::unit()));
    const double anisotropy = r.number("anisotropy", 0.0, {0.0, 0.99});
    const double aspect = std::sqrt(1.0 - 0.9 * anisotropy);
    m.alphaX = std::min(1.0, alpha / aspect);
    m.alphaY = alpha * aspect;
}

void readMicrofacetSwitches(const JsonReader& r, MicrofacetParams& m, bool allowSampling) {
    m.g2 = r.choice(
        "g2", G2Form::HeightCorrelated,
        {{"height_correlated", G2Form::HeightCorrelated}, {"separable", G2Form::Separable}});
    if (!allowSampling) return;
    m.sampling = r.choice("sampling", MicrofacetSampling::VisibleNormals,
                          {{"vndf", MicrofacetSampling::VisibleNormals},
                           {"caps", MicrofacetSampling::SphericalCaps},
                           {"walter", MicrofacetSampling::Walter},
                           {"walter_widened", MicrofacetSampling::WalterWidened}});
    if (m.sampling == MicrofacetSampling::SphericalCaps && m.ndf != NdfKind::Ggx)
        r.failAt("sampling", "\"caps\" (Dupuy and Benyoub 2023) is defined for GGX only");
}

FresnelChoice readFresnel(const JsonReader& r, FresnelChoice defaultValue, bool allowAuto) {
    const FresnelChoice f = r.choice("fresnel", defaultValue,
                                     {{"schlick", FresnelChoice::Schlick},
                                      {"schlick_shadowed", FresnelChoice::SchlickShadowed},
                                      {"schlick_sg", FresnelChoice::SchlickSphericalGaussian},
                                      {"f82", FresnelChoice::F82},
                                      {"exact", FresnelChoice::Exact},
                                      {"auto", FresnelChoice::Auto}});
    if (f == FresnelChoice::Auto && !allowAuto)
        r.failAt("fresnel", "expected one of schlick, schlick_shadowed, schlick_sg, f82, exact");
    return f;
}

StandardMaterial readStandard(const JsonReader& r) {
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
    if (r.has("f82") && r.has("f82_tint")) r.fail("give only one of f82 and f82_tint");
    if (const auto c = r.optionalTriple("f82", Range::unit())) s.f82 = toRgb(*c);
    if (const auto c = r.optionalTriple("f82_tint", Range::nonNegative())) s.f82Tint = toRgb(*c);

    s.diffuse = r.choice<std::optional<DiffuseModel>>("diffuse_model", DiffuseModel::Lambert,
                                                      {{"lambert", DiffuseModel::Lambert},
                                                       {"oren_nayar", DiffuseModel::OrenNayar},
                                                       {"burley", DiffuseModel::Burley},
                                                       {"frostbite", DiffuseModel::Frostbite},
                                                       {"none", std::nullopt}});
    const std::string spec = r.string("specular_model", "ggx");
    if (spec != "ggx" && spec != "beckmann" && spec != "phong" && spec != "none")
        r.failAt("specular_model",
                 "expected one of ggx, beckmann, phong, none, got \"" + spec + "\"");
    s.specularLobe = spec != "none";
    s.phong = spec == "phong";
    s.microfacet.ndf = spec == "beckmann" ? NdfKind::Beckmann : NdfKind::Ggx;
    readRoughness(r, 0.5, s.microfacet);
    readMicrofacetSwitches(r, s.microfacet, true);
    s.fresnel = readFresnel(r, FresnelChoice::SchlickShadowed, false);
    if (s.fresnel == FresnelChoice::Exact && s.metalness > 0)
        r.failAt("fresnel",
                 "\"exact\" is the dielectric Fresnel of `ior`; a metal's exact Fresnel needs "
                 "n and k: use a \"conductor\" material");
    if ((s.f82 || s.f82Tint) && s.fresnel != FresnelChoice::F82)
        r.fail("f82 / f82_tint need \"fresnel\": \"f82\"");
    // The article sums Frostbite's renormalised diffuse and the specular lobe.
    const LayerCoupling defaultCoupling =
        s.diffuse == DiffuseModel::Frostbite ? LayerCoupling::Sum : LayerCoupling::Fresnel;
    s.coupling = r.choice("coupling", defaultCoupling,
                          {{"fresnel", LayerCoupling::Fresnel},
                           {"sum", LayerCoupling::Sum},
                           {"albedo", LayerCoupling::Albedo}});
    s.microfacet.multiscatter = r.boolean("multiscatter", false);
    if (s.phong && s.microfacet.multiscatter)
        r.failAt("multiscatter", "compensates microfacet lobes only, not \"phong\"");
    prepareEnergyTables(s);
    return s;
}

// `layered`: the stack spelled out, an interface over a base with a coupling, built as the
// equivalent `standard` material in the specular workflow (one implementation of the stack).
StandardMaterial readLayered(const JsonReader& r) {
    StandardMaterial s;
    if (const auto i = r.optionalChild("interface")) {
        i->expectObject();
        const std::string model = i->string("model", "ggx");
        if (model != "ggx" && model != "beckmann" && model != "phong")
            i->failAt("model", "expected one of ggx, beckmann, phong, got \"" + model + "\"");
        s.phong = model == "phong";
        s.microfacet.ndf = model == "beckmann" ? NdfKind::Beckmann : NdfKind::Ggx;
        readRoughness(*i, 0.5, s.microfacet);
        readMicrofacetSwitches(*i, s.microfacet, true);
        s.fresnel = readFresnel(*i, FresnelChoice::SchlickShadowed, false);
        const auto ior = i->optionalNumber("ior", Range::positive());
        const auto f0 = i->optionalTriple("f0", Range::unit());
        if (ior) s.ior = *ior;
        const double f0FromIor = sqr((s.ior - 1.0) / (s.ior + 1.0));
        s.specularColor = f0 ? toRgb(*f0) : RgbInput(f0FromIor);
        if (s.fresnel == FresnelChoice::Exact && f0)
            i->failAt("f0", "\"exact\" Fresnel takes the interface's ior, not f0");
        if (i->has("f82") && i->has("f82_tint")) i->fail("give only one of f82 and f82_tint");
        if (const auto c = i->optionalTriple("f82", Range::unit())) s.f82 = toRgb(*c);
        if (const auto c = i->optionalTriple("f82_tint", Range::nonNegative()))
            s.f82Tint = toRgb(*c);
        if ((s.f82 || s.f82Tint) && s.fresnel != FresnelChoice::F82)
            i->fail("f82 / f82_tint need \"fresnel\": \"f82\"");
        s.microfacet.multiscatter = i->boolean("multiscatter", false);
        if (s.phong && s.microfacet.multiscatter)
            i->failAt("multiscatter", "compensates microfacet lobes only, not \"phong\"");
        i->finish();
    } else {
        s.specularLobe = false;
    }
    if (const auto b = r.optionalChild("base")) {
        b->expectObject();
        s.diffuse = b->choice("type", DiffuseModel::Lambert,
                              {{"lambert", DiffuseModel::Lambert},
                               {"oren_nayar", DiffuseModel::OrenNayar},
                               {"burley", DiffuseModel::Burley},
                               {"frostbite", DiffuseModel::Frostbite}});
        s.baseColor = readColor(*b, "reflectance", 0.5);
        if (s.diffuse != DiffuseModel::Lambert) {
            MicrofacetParams m;
            readRoughness(*b, 0.5, m);
            s.diffuseRoughness = m.perceptualRoughness();
        }
        b->finish();
    } else {
        s.diffuse.reset();
    }
    s.transmission = r.number("transmission", 0.0, Range::unit());
    s.coupling =
        r.choice("coupling",
                 s.diffuse == DiffuseModel::Frostbite ? LayerCoupling::Sum : LayerCoupling::Fresnel,
                 {{"fresnel", LayerCoupling::Fresnel},
                  {"sum", LayerCoupling::Sum},
                  {"albedo", LayerCoupling::Albedo}});
    if (!s.specularLobe && !s.diffuse && s.transmission == 0)
        r.fail("a layered material needs an interface, a base or transmission");
    prepareEnergyTables(s);
    return s;
}

DiffuseMaterial readDiffuse(const JsonReader& r, DiffuseModel model) {
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

std::string knownNames(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

// A path in a material relative to the JSON file's directory, else to the working directory.
std::filesystem::path resolvePath(const JsonReader& r, const std::string& key) {
    std::filesystem::path p = r.requiredString(key);
    if (p.is_relative()) {
        const auto beside = (r.source().directory / p).lexically_normal();
        if (std::filesystem::exists(beside) || !std::filesystem::exists(p)) p = beside;
    }
    if (!std::filesystem::exists(p)) r.failAt(key, p.string() + ": no such file");
    return p;
}

std::shared_ptr<const IorSpectrum> loadIorAt(const JsonReader& r, const std::string& key) {
    const std::filesystem::path path = resolvePath(r, key);
    try {
        return std::make_shared<const IorSpectrum>(loadIorFile(path));
    } catch (const InputError& e) {
        r.failAt(key, e.what());
    }
}

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

ConductorMaterial readConductor(const JsonReader& r) {
    ConductorMaterial c;
    const bool etaK = r.has("eta") || r.has("k");
    const bool f0 = r.has("f0") || r.has("f82");
    const bool named = r.has("material"), file = r.has("nk_file");
    if (int(etaK) + int(f0) + int(named) + int(file) != 1)
        r.fail(
            "a conductor's optics are exactly one of {\"material\": name}, {\"eta\", \"k\"}, "
            "{\"nk_file\": path} or {\"f0\", \"f82\"}");
    if (named || file) {
        c.optics.form = ConductorOptics::Form::Spectral;
        if (named) {
            const std::string name = r.requiredString("material");
            const auto ior = namedIor(name);
            if (!ior || ior->k(550) == 0)
                r.failAt("material", "unknown metal \"" + name + "\"; expected one of " +
                                         knownNames(namedMetalNames()));
            c.optics.spectrum = std::make_shared<const IorSpectrum>(*ior);
        } else {
            c.optics.spectrum = loadIorAt(r, "nk_file");
        }
        std::tie(c.optics.f0, c.optics.f82) = conductorF0F82(*c.optics.spectrum);
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
        c.optics.form = ConductorOptics::Form::Spectral;
        c.optics.spectrum = std::make_shared<const IorSpectrum>(
            r.path().empty() ? "eta/k" : r.path(), eta, k, true);
        std::tie(c.optics.f0, c.optics.f82) = conductorF0F82(*c.optics.spectrum);
    } else if (etaK) {
        c.optics.form = ConductorOptics::Form::EtaK;
        c.optics.eta =
            toRgb(r.optionalTriple("eta", Range::positive()).value_or(std::array<double, 3>{}));
        if (!r.has("eta")) r.failAt("eta", "missing; expected a number > 0 or [r, g, b]");
        if (!r.has("k")) r.failAt("k", "missing; expected a number >= 0 or [r, g, b]");
        c.optics.k = toRgb(*r.optionalTriple("k", Range::nonNegative()));
    } else {
        c.optics.form = ConductorOptics::Form::F0F82;
        if (!r.has("f0")) r.failAt("f0", "missing; expected a number in [0, 1] or [r, g, b]");
        c.optics.f0 = toRgb(*r.optionalTriple("f0", Range::unit()));
        if (const auto v = r.optionalTriple("f82", Range::unit())) c.optics.f82 = toRgb(*v);
    }
    c.microfacet.ndf = r.choice("distribution", NdfKind::Ggx,
                                {{"ggx", NdfKind::Ggx},
                                 {"beckmann", NdfKind::Beckmann},
                                 {"blinn_phong", NdfKind::BlinnPhong}});
    readRoughness(r, 0.0, c.microfacet);
    readMicrofacetSwitches(r, c.microfacet, true);
    c.fresnel = readFresnel(r, FresnelChoice::Auto, true);
    c.microfacet.multiscatter = r.boolean("multiscatter", false);
    prepareEnergyTables(c);
    if (c.optics.form == ConductorOptics::Form::F0F82 && c.fresnel == FresnelChoice::Exact)
        r.failAt("fresnel", "\"exact\" needs the eta and k of the conductor, not f0");
    return c;
}

DielectricMaterial readDielectric(const JsonReader& r) {
    DielectricMaterial d;
    if (r.has("ior") && r.has("ior_file")) r.fail("give only one of ior and ior_file");
    if (r.has("ior_file")) {
        d.spectrum = loadIorAt(r, "ior_file");
    } else if (r.has("ior") && r.value()["ior"].is_object()) {
        // Dispersion formulas, wavelength in um:
        //   {"cauchy": [A, B, C]}                n = A + B / l^2 + C / l^4 (C optional)
        //   {"sellmeier": {"b": [...], "c": [...]}}  n^2 = 1 + sum b_i l^2 / (l^2 - c_i)
        const JsonReader f = r.child("ior");
        if (f.has("cauchy") == f.has("sellmeier"))
            f.fail("expected exactly one of cauchy and sellmeier");
        if (f.has("cauchy")) {
            const Json& c = f.value()["cauchy"];
            if (!c.is_array() || c.size() < 2 || c.size() > 3)
                f.failAt("cauchy", "expected [A, B] or [A, B, C] (wavelength in um)");
            std::array<double, 3> k{0, 0, 0};
            for (std::size_t i = 0; i < c.size(); ++i)
                k[i] = f.checkNumber(c[i], f.childPath("cauchy") + "[" + std::to_string(i) + "]",
                                     i == 0 ? Range::positive() : Range::any());
            (void)f.child("cauchy");
            d.spectrum = std::make_shared<const IorSpectrum>(
                "Cauchy",
                [k](double nm) {
                    const double l2 = sqr(nm * 1e-3);
                    return k[0] + k[1] / l2 + k[2] / (l2 * l2);
                },
                [](double) { return 0.0; }, k[1] != 0 || k[2] != 0);
        } else {
            const JsonReader sm = f.child("sellmeier");
            const Json& b = sm.value()["b"];
            const Json& c = sm.value()["c"];
            if (!sm.has("b") || !sm.has("c") || !b.is_array() || !c.is_array() ||
                b.size() != c.size() || b.empty())
                sm.fail(
                    "expected {\"b\": [...], \"c\": [...]} of equal, non-zero length (c in um^2)");
            std::vector<double> bs, cs;
            for (std::size_t i = 0; i < b.size(); ++i) {
                bs.push_back(sm.checkNumber(b[i], sm.childPath("b") + "[" + std::to_string(i) + "]",
                                            Range::any()));
                cs.push_back(sm.checkNumber(c[i], sm.childPath("c") + "[" + std::to_string(i) + "]",
                                            Range::nonNegative()));
            }
            (void)sm.child("b");
            (void)sm.child("c");
            sm.finish();
            d.spectrum = std::make_shared<const IorSpectrum>(
                "Sellmeier",
                [bs, cs](double nm) {
                    const double l2 = sqr(nm * 1e-3);
                    double n2 = 1;
                    for (std::size_t i = 0; i < bs.size(); ++i)
                        n2 += bs[i] * l2 / (l2 - cs[i]);
                    return std::sqrt(std::max(n2, 0.0));
                },
                [](double) { return 0.0; }, true);
        }
        f.finish();
    } else if (r.has("ior") && r.value()["ior"].is_string()) {
        const std::string name = r.requiredString("ior");
        const auto ior = namedIor(name);
        if (!ior || ior->k(550) != 0)
            r.failAt("ior", "unknown glass \"" + name + "\"; expected a number or one of " +
                                knownNames(namedGlassNames()));
        d.spectrum = std::make_shared<const IorSpectrum>(*ior);
    } else {
        d.ior = r.number("ior", 1.5, Range::positive());
    }
    if (d.spectrum) {
        d.ior = d.spectrum->n(kDLineNm);
        if (!(d.ior > 0)) r.fail("the index of refraction at 587.56 nm is not positive");
    }
    d.microfacet.ndf = r.choice("distribution", NdfKind::Ggx,
                                {{"ggx", NdfKind::Ggx}, {"beckmann", NdfKind::Beckmann}});
    readRoughness(r, 0.0, d.microfacet);
    readMicrofacetSwitches(r, d.microfacet, false);
    return d;
}

PhongMaterial readPhong(const JsonReader& r) {
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

MixMaterial readMix(const JsonReader& r) {
    MixMaterial m;
    m.weight = r.number("weight", 0.5, Range::unit());
    m.a = std::make_shared<MaterialDesc>(parseMaterial(r.child("a")));
    m.b = std::make_shared<MaterialDesc>(parseMaterial(r.child("b")));
    return m;
}

}  // namespace

void prepareEnergyTables(ConductorMaterial& c) {
    if (c.microfacet.multiscatter) c.microfacet.energyF1 = microfacetEnergyTable(c.microfacet);
}

void prepareEnergyTables(StandardMaterial& s) {
    if (s.microfacet.multiscatter && s.specularLobe && !s.phong)
        s.microfacet.energyF1 = microfacetEnergyTable(s.microfacet);
    if (s.coupling != LayerCoupling::Albedo) return;
    // The interface alone (with its compensation, if any), from the same builder.
    StandardMaterial interfaceOnly = s;
    interfaceOnly.diffuse.reset();
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

double MicrofacetParams::perceptualRoughness() const {
    return std::sqrt(0.5 * (alphaX + alphaY));
}

bool ConductorOptics::etaKIsGrey() const {
    return eta[0] == eta[1] && eta[1] == eta[2] && k[0] == k[1] && k[1] == k[2];
}

const char* const* materialTypeNames() {
    return kTypeNames;
}

MaterialDesc parseMaterial(const JsonReader& r) {
    r.expectObject();
    MaterialDesc desc;
    desc.type = r.requiredString("type");
    const std::string& t = desc.type;
    if (t == "standard") {
        desc.model = readStandard(r);
    } else if (t == "lambert") {
        desc.model = readDiffuse(r, DiffuseModel::Lambert);
    } else if (t == "oren_nayar") {
        desc.model = readDiffuse(r, DiffuseModel::OrenNayar);
    } else if (t == "burley") {
        desc.model = readDiffuse(r, DiffuseModel::Burley);
    } else if (t == "frostbite") {
        desc.model = readDiffuse(r, DiffuseModel::Frostbite);
    } else if (t == "conductor") {
        desc.model = readConductor(r);
    } else if (t == "dielectric") {
        desc.model = readDielectric(r);
    } else if (t == "layered") {
        desc.model = readLayered(r);
    } else if (t == "phong") {
        desc.model = readPhong(r);
    } else if (t == "mix") {
        desc.model = readMix(r);
    } else {
        std::string list;
        for (const char* const* n = kTypeNames; *n; ++n)
            list += (list.empty() ? "" : ", ") + std::string(*n);
        r.failAt("type", "unknown material type \"" + t + "\"; expected one of " + list);
    }
    r.finish();
    return desc;
}

MaterialDesc parseMaterialArgument(const std::string& argument) {
    if (!argument.empty() && argument[0] == '@') {
        const std::filesystem::path path = argument.substr(1);
        const Json j = readJsonFile(path);
        const JsonSource source{path.string(), path.parent_path()};
        return parseMaterial(JsonReader(j, "", source));
    }
    static const JsonSource source{"<material argument>", "."};
    const Json j = parseJsonText(argument, source);
    return parseMaterial(JsonReader(j, "", source));
}

}  // namespace lamina
