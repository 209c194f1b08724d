// `lamina fresnel` and lamina.fresnel (fresnel.h): the options, the inputs read from them, the
// report, and the result as data.
#include "declarations.h"
#include "lamina/bsdf/material.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

FresnelInputs fresnelInputs(const OptionValues& v, const CommandContext& context) {
    FresnelInputs in;
    in.materials = v.texts("materials");
    in.thinFilmNm = *v.number("thin-film");
    in.thinFilmIor = *v.number("thin-film-ior");
    in.scene = v.text("scene").value_or("");
    in.spp = int(v.integer("spp").value_or(0));
    if (const auto resolution = v.resolution("resolution")) in.overrides.resolution = resolution;
    in.progress = context.progress;
    return in;
}

Data modelData(const FresnelModel& model) {
    std::vector<double> rgb;
    for (const auto& value : model.rgb)
        for (int c = 0; c < 3; ++c)
            rgb.push_back(value[c]);
    Data d = Data::dict();
    d.set("name", model.name);
    d.set("rgb", Data::array(std::move(rgb), {model.rgb.size(), 3}));
    d.set("max_error", model.maxError);
    d.set("mean_error", model.meanError);
    d.set("max_delta_e", model.maxDeltaE);
    d.set("mean_delta_e", model.meanDeltaE);
    return d;
}

Data fresnelData(const OptionValues& v, const CommandContext& context) {
    const FresnelResult r = runFresnel(fresnelInputs(v, context));
    std::vector<double> degrees;
    for (int i = 0; i < kFresnelAngles; ++i)
        degrees.push_back(i);
    Data out = Data::list();
    for (const auto& m : r.materials) {
        Data models = Data::list();
        for (const auto& model : m.models)
            models.append(modelData(model));
        Data spectral = Data::dict();
        for (const auto& curve : m.spectral)
            spectral.set(curve.nm, Data::array(curve.reflectance));
        Data d = Data::dict();
        d.set("material", m.stem);
        d.set("name", m.name);
        d.set("degrees", Data::array(degrees));
        d.set("models", std::move(models));
        d.set("spectral", std::move(spectral));
        out.append(std::move(d));
    }
    return out;
}

}  // namespace

CommandDecl fresnelDeclaration() {
    CommandDecl c;
    c.name = "fresnel";
    c.help =
        "Exact spectral Fresnel against the RGB models (Schlick, shadowed F90, F82, spherical "
        "Gaussian): errors, CIEDE2000, curves, swatches; optionally a scene in both modes";
    c.returns =
        "per material a dict: degrees (0 ... 90), models (the exact colour first, then RGB mode's "
        "models: name, rgb, max_error, mean_error, max_delta_e, mean_delta_e) and spectral (nm -> "
        "the exact reflectance against angle)";
    const FresnelInputs defaults;
    c.options = {
        textListOption("materials",
                       "Metals (Au, Ag, Cu, Al, ...), glasses (bk7, diamond, ...) or n/k files")
            .asPositional()
            .asRequired(),
        numberOption("thin-film",
                     "Put a thin film this many nm thick on every material (0: none); the RGB "
                     "models are then RGB mode's film and the bare material's F82",
                     0.0, ThinFilmParams::kMaxThicknessNm)
            .byDefault(defaults.thinFilmNm),
        numberOption("thin-film-ior", "The index of the --thin-film", 1.0, ThinFilmParams::kMaxIor)
            .byDefault(defaults.thinFilmIor),
        outputDirectoryOption(),
        fileOption("scene", "Also render this scene in both modes and compare")
            .existing()
            .commandLineOnly("the scene's renders and difference maps are report files; in "
                             "Python lamina.render renders both modes and lamina.compare "
                             "compares them"),
        integerOption("spp", "Samples per pixel of the --scene renders", 1, render::kMaxSppOverride)
            .commandLineOnly("of --scene's renders"),
        resolutionOverrideOption().commandLineOnly("of --scene's renders"),
        resumeOption().needing("scene"),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        FresnelInputs in = fresnelInputs(v, context);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            FresnelInputs run = in;
            run.keepDirectory = report.directory();
            writeFresnelReport(runFresnel(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = fresnelData;
    return c;
}

}  // namespace lamina::experiments
