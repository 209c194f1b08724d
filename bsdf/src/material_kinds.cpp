// The list of material types (material_kind.h): each registration lives in its reader file;
// this is the order in which messages, `lamina info` and the scene schema name them.
#include <algorithm>

#include "lamina/bsdf/material_kind.h"

namespace lamina {

extern const MaterialKind kStandardMaterial, kLambertMaterial, kOrenNayarMaterial, kBurleyMaterial,
    kFrostbiteMaterial, kConductorMaterial, kDiffuseTransmissionMaterial, kDielectricMaterial,
    kThinDielectricMaterial, kPhongMaterial, kLayeredMaterial, kMixMaterial, kCoatedMaterial,
    kPolariserMaterial, kRetarderMaterial;

namespace {

// The diffuse models are material types of their own, under their model names.
const MaterialKind* const kMaterialKinds[] = {
    &kStandardMaterial,
    &kLambertMaterial,
    &kOrenNayarMaterial,
    &kBurleyMaterial,
    &kFrostbiteMaterial,
    &kConductorMaterial,
    &kDiffuseTransmissionMaterial,
    &kDielectricMaterial,
    &kThinDielectricMaterial,
    &kPhongMaterial,
    &kLayeredMaterial,
    &kMixMaterial,
    &kCoatedMaterial,
    &kPolariserMaterial,
    &kRetarderMaterial,
};

}  // namespace

std::optional<TexturedParameter> MaterialKind::texturedParameter(std::string_view key) const {
    for (const TexturableKey& t : texturable)
        if (t.key == key) return t.parameter;
    return std::nullopt;
}

std::span<const MaterialKind* const> materialKinds() {
    return kMaterialKinds;
}

const MaterialKind* findMaterialKind(std::string_view name) {
    const auto kind = std::find_if(std::begin(kMaterialKinds), std::end(kMaterialKinds),
                                   [&](const MaterialKind* k) { return k->name == name; });
    return kind == std::end(kMaterialKinds) ? nullptr : *kind;
}

bool needsOrientation(const MaterialDesc& m) {
    const MaterialKind* kind = findMaterialKind(m.type);
    return kind && kind->orient;
}

MaterialDesc orientedMaterial(const MaterialDesc& m, const Frame<double>& frame) {
    MaterialDesc out = m;
    if (const MaterialKind* kind = findMaterialKind(m.type); kind && kind->orient)
        kind->orient(out.model, frame);
    return out;
}

void collectSpectralData(const MaterialDesc& m, std::vector<std::string>& out) {
    const MaterialKind* kind = findMaterialKind(m.type);
    if (!kind) return;  // a description built by hand with no type name
    if (kind->spectralData) kind->spectralData(m.model, out);
    if (kind->nested)
        for (const MaterialDesc* inner : kind->nested(m.model))
            collectSpectralData(*inner, out);
}

}  // namespace lamina
