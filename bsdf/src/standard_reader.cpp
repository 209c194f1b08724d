// `standard` and `layered`: two spellings of one stack, a specular interface over a diffuse
// base with transmission, both read into StandardMaterial (docs/bsdf.md, "Materials").
#include <cmath>

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
        auto conductor = std::get<ConductorMaterial>(readConductor(b));
        const MicrofacetParams& m = conductor.microfacet;
        if (std::max(m.alphaX, m.alphaY) < kSmoothAlpha)
            b.fail(
                "a conductor base needs a roughness (alpha >= 0.001): a smooth one would be a "
                "second delta lobe under the interface, which the stack does not have");
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

}  // namespace lamina
