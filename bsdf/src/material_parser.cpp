// JSON -> MaterialDesc, with validation (docs/bsdf.md, "Materials"): the table of material
// types, each with its reader (material_readers.h). A new material type is one entry here.
#include <algorithm>
#include <string_view>

#include "material_readers.h"

namespace lamina {

namespace {

MaterialModel readMix(const JsonReader& r) {
    MixMaterial m;
    m.weight = r.number("weight", 0.5, Range::unit());
    m.a = std::make_shared<MaterialDesc>(parseMaterial(r.child("a")));
    m.b = std::make_shared<MaterialDesc>(parseMaterial(r.child("b")));
    return m;
}

struct MaterialType {
    std::string_view name;
    MaterialModel (*read)(const JsonReader&);
};

// Every material type, in the order messages list them. The diffuse models are material types
// of their own, under their model names.
constexpr MaterialType kMaterialTypes[] = {
    {"standard", readStandard},
    {kDiffuseModelNames.name(DiffuseModel::Lambert), readDiffuseModel<DiffuseModel::Lambert>},
    {kDiffuseModelNames.name(DiffuseModel::OrenNayar), readDiffuseModel<DiffuseModel::OrenNayar>},
    {kDiffuseModelNames.name(DiffuseModel::Burley), readDiffuseModel<DiffuseModel::Burley>},
    {kDiffuseModelNames.name(DiffuseModel::Frostbite), readDiffuseModel<DiffuseModel::Frostbite>},
    {"conductor", readConductor},
    {"diffuse_transmission", readDiffuseTransmission},
    {"dielectric", readDielectric},
    {"thin_dielectric", readThinDielectric},
    {"phong", readPhong},
    {"layered", readLayered},
    {"mix", readMix},
    {"coated", readCoated},
};

}  // namespace

std::vector<std::string> materialTypeNames() {
    std::vector<std::string> names;
    for (const auto& t : kMaterialTypes)
        names.emplace_back(t.name);
    return names;
}

MaterialDesc parseMaterial(const JsonReader& r) {
    r.expectObject();
    MaterialDesc desc;
    r.noteNames("type", materialTypeNames());
    desc.type = r.requiredString("type");
    const auto type = std::find_if(std::begin(kMaterialTypes), std::end(kMaterialTypes),
                                   [&](const MaterialType& t) { return t.name == desc.type; });
    if (type == std::end(kMaterialTypes))
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
