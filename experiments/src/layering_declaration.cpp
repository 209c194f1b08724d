// `lamina layering` and lamina.layering (layering.h): the options, the inputs read from them,
// the report, and the result as data.
#include <limits>

#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/layering.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

LayeringInputs layeringInputs(const OptionValues& v, const CommandContext& context) {
    LayeringInputs in;
    in.materials = v.texts("materials");
    in.estimates = int(*v.integer("estimates"));
    in.albedoSamples = int(*v.integer("albedo-samples"));
    in.seed = std::uint64_t(*v.integer("seed"));
    in.scene = v.text("scene").value_or("");
    in.spp = int(v.integer("spp").value_or(0));
    in.resolution = v.resolution("resolution");
    in.progress = context.progress;
    return in;
}

/// The means and the standard errors of a set of estimates, as two arrays.
std::pair<Data, Data> meansOf(const std::vector<MeanEstimate>& values) {
    std::vector<double> mean, se;
    for (const MeanEstimate& v : values) {
        mean.push_back(v.mean);
        se.push_back(v.standardError);
    }
    return {Data::array(std::move(mean)), Data::array(std::move(se))};
}

Data twinData(const LayeringTwinResult& t, std::size_t angles) {
    Data d = Data::dict();
    d.set("name", t.name);
    d.set("material", t.json);
    auto [albedo, albedoSe] = meansOf(t.albedo.values);
    d.set("albedo", std::move(albedo));
    d.set("albedo_se", std::move(albedoSe));
    std::vector<double> error, errorSe;
    for (const TwinComparison& c : t.map.comparisons) {
        error.push_back(c.error);
        errorSe.push_back(c.standardError);
    }
    Data agreement = Data::list();
    for (const TwinComparison& c : t.albedo.comparisons)
        agreement.append(kAgreementNames.name(c.agreement));
    d.set("albedo_agreement", std::move(agreement));
    d.set("map_error", Data::array(std::move(error), {angles, angles}));
    d.set("map_error_se", Data::array(std::move(errorSe), {angles, angles}));
    return d;
}

Data layeringData(const OptionValues& v, const CommandContext& context) {
    const LayeringResult r = runLayering(layeringInputs(v, context));
    Data out = Data::list();
    for (const auto& m : r.materials) {
        Data d = Data::dict();
        d.set("material", m.json);
        d.set("note", m.twinNote);
        // 0: the unbiased walk; otherwise its cap, and the walk is not a truth.
        d.set("walk_max_depth", m.walkMaxDepth);
        d.set("theta_o", Data::numbers(r.albedoAngles));
        auto [walk, walkSe] = meansOf(m.walkAlbedo.values);
        d.set("walk_albedo", std::move(walk));
        d.set("walk_albedo_se", std::move(walkSe));
        d.set("map_angles", Data::numbers(r.mapAngles));
        Data twins = Data::list();
        for (const auto& t : m.twins)
            twins.append(twinData(t, r.mapAngles.size()));
        d.set("twins", std::move(twins));
        out.append(std::move(d));
    }
    return out;
}

}  // namespace

CommandDecl layeringDeclaration() {
    const LayeringInputs defaults;
    std::string builtIns;
    for (const auto& [name, json] : layeringMaterials())
        builtIns += (builtIns.empty() ? "" : ", ") + name;
    CommandDecl c;
    c.name = "layering";
    c.help =
        "Coated materials (random walk) against their analytic layered twins (fresnel and "
        "albedo coupling): albedo, lobes, error maps with standard errors, CIEDE2000 of renders";
    c.returns =
        "per coated material a dict: material, note, theta_o, walk_albedo and walk_albedo_se, "
        "map_angles, and twins (per twin: name, material, albedo, albedo_se, albedo_agreement, "
        "map_error and map_error_se over (theta_o, theta_i))";
    c.options = {
        textListOption("materials",
                       "Coated materials: JSON, @file.json or a built-in name (" + builtIns + ")")
            .asPositional()
            .asRequired(),
        outputDirectoryOption(),
        integerOption("estimates",
                      "Independent walk estimates per eval point (each of the material's "
                      "`samples` walks)",
                      2, 1 << 24)
            .byDefault(defaults.estimates),
        integerOption("albedo-samples", "sample() calls per albedo angle", 2, 1 << 26)
            .byDefault(defaults.albedoSamples),
        integerOption("seed", "Seed of the estimates and the renders", 0,
                      std::numeric_limits<long long>::max())
            .byDefault(static_cast<long long>(defaults.seed)),
        fileOption("scene",
                   "A test-object scene with a material named \"sample\", rendered with the walk "
                   "and each twin in both modes (e.g. scenes/layering/test-object.json)")
            .existing()
            .commandLineOnly("the renders and their CIEDE2000 maps are report files; in "
                             "Python lamina.render renders a scene with each material"),
        integerOption("spp", "Samples per pixel of every --scene render", 1,
                      render::kMaxSppOverride)
            .commandLineOnly("of --scene's renders"),
        resolutionOverrideOption().commandLineOnly("of --scene's renders"),
        resumeOption().needing("scene"),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        LayeringInputs in = layeringInputs(v, context);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            LayeringInputs run = in;
            run.keepDirectory = report.directory();
            writeLayeringReport(runLayering(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = layeringData;
    return c;
}

}  // namespace lamina::experiments
