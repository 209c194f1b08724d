// `mix`: a stochastic blend of two materials (docs/bsdf.md, "Materials").
#include <algorithm>
#include <string>

#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/mix.h"
#include "material_readers.h"

namespace lamina {

namespace {

// How many mixes nest inside each other in `m`, itself included (0: `m` is no mix).
int mixNesting(const MaterialDesc& m) {
    if (!m.model.holds<MixMaterial>()) return 0;
    const auto& x = m.model.as<MixMaterial>();
    return 1 + std::max(mixNesting(*x.a), mixNesting(*x.b));
}

MaterialModel readMix(const JsonReader& r) {
    MixMaterial m;
    m.weight = r.number("weight", 0.5, Range::unit());
    m.a = std::make_shared<MaterialDesc>(parseMaterial(r.child("a")));
    m.b = std::make_shared<MaterialDesc>(parseMaterial(r.child("b")));
    // A polariser's or retarder's axis is turned into each hit's frame at the top of the
    // material only (material_kind.h, orient).
    for (const char* key : {"a", "b"})
        if (needsOrientation(key[0] == 'a' ? *m.a : *m.b))
            r.failAt(key, "a " + (key[0] == 'a' ? m.a : m.b)->type +
                              " is an optical sheet of its own: it cannot be mixed");
    // The inner mixes were read first: the first to go too deep is this one, the outermost of
    // kMaxMixNesting + 1.
    const int nesting = 1 + std::max(mixNesting(*m.a), mixNesting(*m.b));
    if (nesting > kMaxMixNesting)
        r.fail(std::to_string(nesting) + " mixes nest inside each other; at most " +
               std::to_string(kMaxMixNesting) +
               " can (a delta sample records in 16 bits which material of each mix drew it)");
    return m;
}

std::vector<const MaterialDesc*> mixNested(const MaterialModel& model) {
    const auto& m = model.as<MixMaterial>();
    return {m.a.get(), m.b.get()};
}

}  // namespace

// The registration of `mix` (material_kind.h; listed in material_kinds.cpp).
extern const MaterialKind kMixMaterial{
    .name = "mix",
    .listPosition = 120,
    .read = readMix,
    .schema = R"json({
  "type": "object",
  "description": "A stochastic blend of two materials: a with probability 1 - weight, b with weight.",
  "required": ["type"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "mix"},
    "weight": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.5},
    "a": {"$ref": "#/$defs/material"},
    "b": {"$ref": "#/$defs/material"}
  },
  "examples": [
    {
      "type": "mix",
      "weight": 0.3,
      "a": {"type": "lambert", "reflectance": 0.8},
      "b": {"type": "conductor", "material": "Cu"}
    }
  ]
})json",
    .nested = mixNested,
    .polarisation = "as its materials a and b: the weighted sum of their Mueller matrices",
    .transmits = [](const MaterialModel& m) {
        const auto& x = m.as<MixMaterial>();
        return materialTransmits(*x.a) || materialTransmits(*x.b);
    }};

}  // namespace lamina
