// The list of material types (material_kind.h): each registration lives in its reader file, and
// the build lists the reader files' registrations (cmake/GenerateBsdfRegistry.cmake).
#include <algorithm>
#include <vector>

#include "lamina/bsdf/material_kind.h"

namespace lamina {

#include "material_kind_list.inc"

namespace {

// The registered types by listPosition (ties by name, so the order never depends on the files').
std::vector<const MaterialKind*> orderedKinds() {
    std::vector<const MaterialKind*> kinds(std::begin(kRegisteredMaterialKinds),
                                           std::end(kRegisteredMaterialKinds));
    std::sort(kinds.begin(), kinds.end(), [](const MaterialKind* a, const MaterialKind* b) {
        return a->listPosition != b->listPosition ? a->listPosition < b->listPosition
                                                  : a->name < b->name;
    });
    return kinds;
}

const std::vector<const MaterialKind*>& kinds() {
    static const std::vector<const MaterialKind*> ordered = orderedKinds();
    return ordered;
}

}  // namespace

std::optional<TexturedParameter> MaterialKind::texturedParameter(std::string_view key) const {
    for (const TexturableKey& t : texturable)
        if (t.key == key) return t.parameter;
    return std::nullopt;
}

std::span<const MaterialKind* const> materialKinds() {
    return kinds();
}

const MaterialKind* findMaterialKind(std::string_view name) {
    const auto kind = std::find_if(kinds().begin(), kinds().end(),
                                   [&](const MaterialKind* k) { return k->name == name; });
    return kind == kinds().end() ? nullptr : *kind;
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

bool materialTransmits(const MaterialDesc& m) {
    const MaterialKind* kind = findMaterialKind(m.type);
    return kind && kind->transmits && kind->transmits(m.model);
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
