#include "lamina/experiments/layering_twins.h"
#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/layered.h"

#include <algorithm>
#include <filesystem>

#include "lamina/core/error.h"
#include "lamina/core/json_reader.h"

namespace lamina::experiments {

const std::vector<std::pair<std::string, std::string>>& layeringMaterials() {
    static const std::vector<std::pair<std::string, std::string>> materials = {
        // A smooth clear coat over a red paint.
        {"clear-paint",
         R"({"type": "coated", "ior": 1.5, "base": {"type": "lambert", "reflectance": [0.6, 0.06, 0.04]}})"},
        // A slightly rough varnish over a rough brown diffuse (a wood-like finish).
        {"varnished-wood",
         R"({"type": "coated", "ior": 1.55, "roughness": 0.2, "base": {"type": "oren_nayar", "reflectance": [0.45, 0.25, 0.12], "roughness": 0.6}})"},
        // A thin rough coat over rough gold (its n, k relative to the coat).
        {"coated-gold",
         R"({"type": "coated", "ior": 1.5, "roughness": 0.15, "base": {"type": "conductor", "material": "Au", "roughness": 0.3}})"},
        // A thick coat whose medium scatters and tints (warm albedo, forward scattering) over
        // a light grey diffuse.
        {"tinted-coat",
         R"({"type": "coated", "ior": 1.5, "roughness": 0.1, "thickness": 1.0, "albedo": [0.9, 0.55, 0.25], "g": 0.4, "base": {"type": "lambert", "reflectance": 0.8}})"},
    };
    return materials;
}

LayeringMaterial readLayeringMaterial(const std::string& argument, int index) {
    LayeringMaterial m;
    Json j;
    JsonSource source;
    if (!argument.empty() && argument[0] == '@') {
        const std::filesystem::path path = argument.substr(1);
        j = readJsonFile(path);
        source = JsonSource{path.string(), path.parent_path()};
        m.stem = path.stem().string();
    } else if (!argument.empty() && argument.find('{') != std::string::npos) {
        source = JsonSource{"<material argument " + std::to_string(index) + ">", "."};
        j = parseJsonText(argument, source);
        m.stem = "material" + std::to_string(index);
    } else {
        std::string known;
        for (const auto& [name, json] : layeringMaterials()) {
            known += (known.empty() ? "" : ", ") + name;
            if (name != argument) continue;
            source = JsonSource{"<built-in material " + name + ">", "."};
            j = parseJsonText(json, source);
            m.stem = name;
        }
        if (m.stem.empty())
            throw InputError("unknown material \"" + argument + "\": expected a built-in name (" +
                             known + "), a JSON object or @file.json");
    }
    const JsonReader reader(j, "", source);
    m.desc = parseMaterial(reader);
    if (!m.desc.model.holds<CoatedMaterial>())
        reader.failAt("type",
                      "expected \"coated\": lamina layering compares coated materials "
                      "with their analytic twins");
    m.json = j.dump();
    return m;
}

std::vector<LayeringTwin> analyticTwins(const LayeringMaterial& m, std::string& note) {
    note.clear();
    const CoatedMaterial& c = m.coated();
    const auto* conductor = c.base->model.get<ConductorMaterial>();
    const bool smoothConductor = conductor && std::max(conductor->microfacet.alphaX,
                                                       conductor->microfacet.alphaY) < kSmoothAlpha;
    if ((!c.base->model.holds<DiffuseMaterial>() && !conductor) || smoothConductor) {
        note =
            "no analytic twin: the layered stack (bsdf/layered.h) takes a diffuse base "
            "(lambert, oren_nayar, burley, frostbite) or a rough conductor, and this base is " +
            std::string(smoothConductor ? "a smooth conductor" : "a " + c.base->type);
        return {};
    }
    if (conductor)
        note =
            "the twins of a conductor base are one pass through the coat "
            "(bsdf/refracted_conductor.h): the conductor is evaluated at wo and wi refracted "
            "into the coat, and the light the coat reflects back onto it, or that it sends "
            "beyond the critical angle, is not followed";
    if (c.thickness > 0)
        note += std::string(note.empty() ? "" : "; ") +
                "the layered stack has no medium between its layers: the twins are the same "
                "coat and base without the medium, so the error includes everything the "
                "medium does (absorption, scattering, tint)";
    const Json original = Json::parse(m.json);
    Json interface = {
        {"model", std::string(kNdfKindNames.name(c.microfacet.ndf))},
        {"alpha_x", c.microfacet.alphaX},
        {"alpha_y", c.microfacet.alphaY},
        {"ior", c.ior},
        {"fresnel", "exact"},
        {"g2", std::string(kG2FormNames.name(c.microfacet.g2))},
    };
    std::vector<LayeringTwin> twins;
    for (const LayerCoupling coupling : {LayerCoupling::Fresnel, LayerCoupling::Albedo}) {
        const std::string couplingName(kLayerCouplingNames.name(coupling));
        const Json twin = {{"type", "layered"},
                           {"interface", interface},
                           {"base", original.at("base")},
                           {"coupling", couplingName}};
        LayeringTwin t;
        t.name = couplingName + " coupling";
        t.json = twin.dump();
        t.desc = parseMaterialArgument(t.json);
        twins.push_back(std::move(t));
    }
    return twins;
}

}  // namespace lamina::experiments
