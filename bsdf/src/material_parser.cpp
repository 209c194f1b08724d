// JSON -> MaterialDesc, with validation (docs/bsdf.md, "Materials"): the type's registration
// (material_kind.h) reads its keys.
#include <algorithm>
#include <string_view>

#include "lamina/bsdf/material_kind.h"
#include "material_readers.h"

namespace lamina {

std::vector<std::string> materialTypeNames() {
    std::vector<std::string> names;
    for (const MaterialKind* kind : materialKinds())
        names.emplace_back(kind->name);
    return names;
}

MaterialDesc parseMaterial(const JsonReader& r) {
    r.expectObject();
    MaterialDesc desc;
    r.noteNames("type", materialTypeNames());
    desc.type = r.requiredString("type");
    const MaterialKind* type = findMaterialKind(desc.type);
    if (!type)
        r.failAt("type", "unknown material type \"" + desc.type + "\"; expected one of " +
                             knownNames(materialTypeNames()));
    desc.model = type->read(r);
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
