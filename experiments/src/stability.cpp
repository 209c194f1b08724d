#include "lamina/experiments/stability.h"
#include "lamina/experiments/interrupted.h"

#include <nlohmann/json.hpp>

#include "lamina/bsdf/material_builder.h"
#include "lamina/core/error.h"
#include "lamina/render/renderer.h"
#include "lamina/spectral/color_space.h"

namespace lamina::experiments {

const std::vector<std::string>& defaultStabilityMaterials() {
    static const std::vector<std::string> m = {
        R"({"type":"conductor","material":"Au"})",
        R"({"type":"conductor","eta":0.5,"k":20})",
        R"({"type":"conductor","distribution":"beckmann","eta":0.4,"k":3})",
        R"({"type":"dielectric","ior":1.5})",
        R"({"type":"dielectric","ior":0.6666666666666666})",
        R"({"type":"dielectric","ior":4})",
        R"({"type":"standard","base_color":1})",
        R"({"type":"standard","base_color":[1,0.8,0.3],"metalness":1})",
        R"({"type":"standard","base_color":1,"transmission":0.7})",
        R"({"type":"lambert","reflectance":1})",
        R"({"type":"oren_nayar","reflectance":1,"roughness":1})",
        R"({"type":"burley","reflectance":1,"roughness":1})",
    };
    return m;
}

namespace {

/// The material with its roughness replaced by alpha, or nullopt if it has none.
std::optional<MaterialDesc> withAlpha(const std::string& json, double alpha) {
    nlohmann::json j = nlohmann::json::parse(json);
    j.erase("roughness");
    j["alpha"] = alpha;
    try {
        return parseMaterialArgument(j.dump());
    } catch (const InputError&) {
        return std::nullopt;
    }
}

AuditedModel audit(const std::string& json, int samples) {
    parseMaterialArgument(json);  // a clear error for a bad material
    const bool rough = withAlpha(json, 0.5).has_value();
    StabilityModel model;
    model.makeDouble = [&](double alpha) {
        const MaterialDesc m = rough ? *withAlpha(json, alpha) : parseMaterialArgument(json);
        return buildBxdf(m, SpectrumContext<Rgb<double>>{});
    };
    model.makeFloat = [&](double alpha) {
        const MaterialDesc m = rough ? *withAlpha(json, alpha) : parseMaterialArgument(json);
        return buildBxdf(m, SpectrumContext<Rgb<float>>{});
    };
    AuditedModel m{json,
                   auditStability(model, rough ? kStabilityAlphas : std::vector<double>{0.0},
                                  kStabilityCosines, 64, samples),
                   {}};
    m.polarised = auditPolarisedStability(
        [&](double alpha) { return rough ? *withAlpha(json, alpha) : parseMaterialArgument(json); },
        rough ? kPolarisedStabilityAlphas : std::vector<double>{0.0}, probedIndices(json));
    return m;
}

StiffSceneRender renderStiffScene(const std::string& path, int spp) {
    const render::SceneDesc scene = render::loadScene(path);
    render::RenderOptions o;
    o.spp = spp;
    const render::RenderResult r = renderWhole(scene, o);
    double mean = 0;
    for (int y = 0; y < r.film->height(); ++y)
        for (int x = 0; x < r.film->width(); ++x)
            mean += luminance(r.film->pixel(x, y));
    mean /= double(r.film->width()) * r.film->height();
    return {path, r.film->rejectedSamples(), r.film->largestSampleLuminance(), mean};
}

}  // namespace

StabilityResult runStability(const StabilityInputs& in) {
    StabilityResult result{in, {}, {}};
    const std::vector<std::string>& materials =
        in.materials.empty() ? defaultStabilityMaterials() : in.materials;
    for (const std::string& json : materials) {
        stopIfInterrupted();
        result.models.push_back(audit(json, in.samples));
        tell(in.progress, "audited " + json + "\n");
    }
    for (const std::string& s : in.scenes) {
        result.scenes.push_back(renderStiffScene(s, in.spp));
        tell(in.progress, "rendered " + s + "\n");
    }
    return result;
}

}  // namespace lamina::experiments
