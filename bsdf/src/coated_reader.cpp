// `coated`: a dielectric coat over a base material without transmission, with an optional
// homogeneous medium between them (docs/bsdf.md, "coated").
#include "material_readers.h"

namespace lamina {

namespace {

constexpr auto kCoatNdfNames = kNdfKindNames.subset(std::array{NdfKind::Ggx, NdfKind::Beckmann});

// A base transmits if any part of it is a dielectric boundary or a transmission lobe: the walk
// has no way below the base.
bool transmits(const MaterialDesc& m) {
    return std::visit(
        [](const auto& x) -> bool {
            using M = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<M, DielectricMaterial> ||
                          std::is_same_v<M, ThinDielectricMaterial>)
                return true;
            if constexpr (std::is_same_v<M, DiffuseTransmissionMaterial>)
                return x.transmittance.rgb.maxValue() > 0 || x.transmittance.spectrum;
            if constexpr (std::is_same_v<M, StandardMaterial>) return x.transmission > 0;
            if constexpr (std::is_same_v<M, MixMaterial>) return transmits(*x.a) || transmits(*x.b);
            if constexpr (std::is_same_v<M, CoatedMaterial>) return transmits(*x.base);
            return false;
        },
        m.model);
}

}  // namespace

MaterialModel readCoated(const JsonReader& r) {
    CoatedMaterial c;
    c.ior = r.number("ior", 1.5, Range::positive());
    c.microfacet.ndf = r.choice("distribution", NdfKind::Ggx, kCoatNdfNames);
    readRoughness(r, 0.0, c.microfacet);
    readMicrofacetSwitches(r, c.microfacet, false);
    if (!r.has("base")) r.failAt("base", "missing; expected a material without transmission");
    c.base = std::make_shared<MaterialDesc>(parseMaterial(r.child("base")));
    if (transmits(*c.base))
        r.failAt("base",
                 "expected a material without transmission (no dielectric or thin_dielectric, "
                 "no diffuse_transmission, no standard or layered transmission)");
    c.thickness = r.number("thickness", 0.0, {0.0, 1e3});
    c.albedo = readColor(r, "albedo", 0.0);
    c.g = r.number("g", 0.0, {-0.99, 0.99});
    // Under a smooth coat, a path whose last non-delta event (a diffuse bounce, a scattering)
    // is followed by delta bounces between the coat and a specular base reaches wi along one
    // direction only: neither the walk's sampling nor its connections find it, so eval would
    // miss it. Such stacks are refused rather than rendered too dark.
    const std::uint32_t baseFlags = buildBxdf(*c.base, SpectrumContext<Rgb<double>>{})->flags();
    const bool smoothCoat = std::max(c.microfacet.alphaX, c.microfacet.alphaY) < kSmoothAlpha;
    const bool scatters = c.thickness > 0 && (c.albedo.rgb.maxValue() > 0 || c.albedo.spectrum);
    if (smoothCoat && isSpecular(baseFlags) &&
        (scatters || (baseFlags & (kLobeDiffuse | kLobeGlossy)) != 0))
        r.failAt("base",
                 "a smooth coat over a base with a smooth (delta) lobe needs a base of "
                 "delta lobes only and no scattering medium; give the coat or the base "
                 "a roughness");
    c.maxDepth = r.integer("max_depth", 10, 1, 1000);
    c.samples = r.integer("samples", 1, 1, 256);
    return c;
}

}  // namespace lamina
