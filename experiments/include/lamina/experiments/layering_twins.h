// The materials of `lamina layering` and their analytic twins.
//
// A material is a `coated` one, named like the other commands' materials (a JSON object
// literal or "@file.json", as `lamina bsdf` and `stability` take them) or by a built-in name
// of the set users meet (clear-coated paint, varnished wood-like diffuse, coated gold, a thick
// tinted coat). Its analytic twins are the `layered` stack (bsdf/layered.h, the stack
// `standard` builds) with the same interface, the coat's index with the exact dielectric
// Fresnel, its NDF, alpha and G2, over the same base, with the article's (1 - F) coupling and
// with the albedo coupling. They are written as `layered` JSON and read by the material
// reader, so a twin is exactly what a user gets from that JSON.
//
// The layered stack takes diffuse bases (lambert, oren_nayar, burley, frostbite) and rough
// conductors (one pass through the coat, bsdf/refracted_conductor.h): a coat over any other base
// (a smooth conductor, another coated material, a mix) has no analytic twin, and the stack has
// no medium between its layers, so a coat with a medium is compared with the twins of the same
// coat without it (what the medium adds is then part of the error).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/material.h"

namespace lamina::experiments {

/// The built-in materials, in report order: (name, JSON).
const std::vector<std::pair<std::string, std::string>>& layeringMaterials();

struct LayeringMaterial {
    std::string stem;  ///< a file-name stem for the report
    std::string json;  ///< the material's JSON text
    MaterialDesc desc;
    const CoatedMaterial& coated() const { return desc.model.as<CoatedMaterial>(); }
};

/// A built-in name, a JSON object literal or "@file.json"; `index` (from 1) names a literal
/// in the report. InputError if it is not a coated material.
LayeringMaterial readLayeringMaterial(const std::string& argument, int index);

struct LayeringTwin {
    std::string name;  ///< "fresnel coupling", "albedo coupling"
    std::string json;
    MaterialDesc desc;
};

/// The twins of `m` (none for a base the stack cannot take); `note` says why there are none,
/// or what the twins leave out (a medium), or is left empty.
std::vector<LayeringTwin> analyticTwins(const LayeringMaterial& m, std::string& note);

}  // namespace lamina::experiments
