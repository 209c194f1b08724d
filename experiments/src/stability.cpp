#include "lamina/experiments/stability.h"

#include <nlohmann/json.hpp>

#include "lamina/experiments/interrupted.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/text_format.h"
#include "stability_kept.h"

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

StiffSceneRender stiffScene(const std::string& path, const render::RenderResult& r) {
    double mean = 0;
    for (int y = 0; y < r.film->height(); ++y)
        for (int x = 0; x < r.film->width(); ++x)
            mean += luminance(r.film->pixel(x, y));
    mean /= double(r.film->width()) * r.film->height();
    return {path, r.film->rejectedSamples(), r.film->largestSampleLuminance(), mean};
}

/// "scene01_tiny-bright-light": a kept render's name.
std::string renderName(std::size_t index, const std::string& path) {
    return formatText("scene%02zu_", index) + std::filesystem::path(path).stem().string();
}

}  // namespace

Data auditedModelData(const AuditedModel& m) {
    const StabilityReport& a = m.audit;
    std::vector<int> issues;
    std::vector<double> floatError;
    for (std::size_t i = 0; i < a.alphas.size(); ++i)
        for (std::size_t j = 0; j < a.cosines.size(); ++j) {
            issues.push_back(a.at(i, j).issues());
            floatError.push_back(a.at(i, j).worstFloatError);
        }
    const std::vector<std::size_t> shape = {a.alphas.size(), a.cosines.size()};
    const StabilityCell t = a.total();
    Data d = Data::dict();
    d.set("material", m.json);
    d.set("alphas", Data::numbers(a.alphas));
    d.set("cosines", Data::numbers(a.cosines));
    d.set("issues", Data::array(std::move(issues), shape));
    d.set("worst_float_error", Data::array(std::move(floatError), shape));
    d.set("nan", t.nan);
    d.set("inf", t.inf);
    d.set("negative", t.negative);
    d.set("weight_mismatch", t.weightMismatch);
    d.set("energy_gain", t.energyGain);
    d.set("evaluations", t.evaluations);
    d.set("samples", t.samples);
    const PolarisedStabilityReport& p = m.polarised;
    Data polarised = Data::dict();
    polarised.set("evaluations", p.evaluations);
    polarised.set("nan", p.nan);
    polarised.set("inf", p.inf);
    polarised.set("worst_jump_float", p.worstJumpFloat);
    polarised.set("worst_jump_double", p.worstJumpDouble);
    polarised.set("discontinuities", p.discontinuities);
    d.set("polarised", std::move(polarised));
    return d;
}

StabilityResult runStability(const StabilityInputs& in) {
    StabilityResult result{in, {}, {}};
    const std::vector<std::string>& materials =
        in.materials.empty() ? defaultStabilityMaterials() : in.materials;
    KeptRenders kept(in.keepDirectory, in.resume);
    std::vector<std::filesystem::path> keptAudits;
    try {
        for (std::size_t i = 0; i < materials.size(); ++i) {
            stopIfInterrupted();
            const std::string& json = materials[i];
            const std::filesystem::path file = keptAuditFile(i + 1);
            const std::filesystem::path path = in.keepDirectory / file;
            if (!in.keepDirectory.empty() && in.resume && std::filesystem::exists(path)) {
                result.models.push_back(readKeptAudit(path, json, in.samples));
                tell(in.progress, json + ": kept from " + file.string() + "\n");
                continue;
            }
            result.models.push_back(audit(json, in.samples));
            if (!in.keepDirectory.empty()) {
                writeKeptAudit(path, result.models.back(), in.samples);
                keptAudits.push_back(path);
            }
            tell(in.progress, "audited " + json + "\n");
        }
        render::RenderOptions o = in.overrides;
        o.spp = in.spp;
        for (std::size_t i = 0; i < in.scenes.size(); ++i) {
            stopIfInterrupted();
            const std::string& s = in.scenes[i];
            const render::SceneDesc scene = render::loadScene(s);
            result.scenes.push_back(
                stiffScene(s, kept.render(renderName(i + 1, s), scene, o, in.progress, s)));
        }
    } catch (Interrupted& stopped) {
        kept.describe(stopped);
        std::string audits;
        for (const std::filesystem::path& p : keptAudits)
            audits += (audits.empty() ? "" : ", ") + p.string();
        if (!audits.empty())
            stopped.kept =
                audits + (stopped.kept.empty() ? " (the same command with --resume continues from "
                                                 "them without auditing them again)"
                                               : ", " + stopped.kept);
        Data models = Data::list();
        for (const AuditedModel& m : result.models)
            models.append(auditedModelData(m));
        stopped.partial->set("models", std::move(models));
        throw;
    }
    return result;
}

}  // namespace lamina::experiments
