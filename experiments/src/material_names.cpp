#include "lamina/experiments/material_names.h"

#include <filesystem>

#include "lamina/core/error.h"

namespace lamina::experiments {

std::string knownMaterialNames() {
    std::string known;
    for (const auto& m : namedMetalNames())
        known += (known.empty() ? "" : " ") + m;
    for (const auto& g : namedGlassNames())
        known += " " + g;
    return known;
}

bool mayBeMaterial(const std::string& name) {
    return namedIor(name).has_value() || std::filesystem::is_regular_file(name);
}

IorSpectrum loadNamedMaterial(const std::string& name) {
    if (auto ior = namedIor(name)) return *ior;
    if (std::filesystem::exists(name)) return loadIorFile(name);
    throw InputError("unknown material \"" + name + "\": expected a metal or glass name (" +
                     knownMaterialNames() + ") or an n/k file (YAML or CSV)");
}

bool isConductor(const IorSpectrum& ior) {
    for (double nm = 380; nm <= 780; nm += 10)
        if (ior.k(nm) > 0) return true;
    return false;
}

}  // namespace lamina::experiments
