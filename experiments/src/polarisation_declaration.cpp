// `lamina polarisation` and lamina.polarisation (polarisation.h, polarisation_materials.h): the
// options, the inputs read from them, the report, and the result as data. One positional list:
// a scene file goes to the scene mode, anything else is a material (material_names.h).
#include <cmath>
#include <filesystem>

#include "declarations.h"
#include "lamina/core/error.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/material_names.h"
#include "lamina/experiments/noise_floor.h"
#include "lamina/experiments/polarisation.h"
#include "lamina/experiments/polarisation_materials.h"
#include "lamina/experiments/text_format.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

/// The options of each mode alone (the dolp threshold and the wavelengths have defaults, so
/// whether they were given cannot be told from their values: they are not checked).
const std::vector<std::string> kSceneOnly = {"spp",       "seed",       "integrator", "threads",
                                             "max-depth", "resolution", "resume"};
const std::vector<std::string> kMaterialsOnly = {"wavelengths"};

/// A scene file: an existing file in one of the formats lamina reads by extension.
bool isSceneFile(const std::filesystem::path& p) {
    const std::string e = p.extension().string();
    const bool sceneExtension = e == ".json" || e == ".pbrt" || e == ".xml" ||
                                (e == ".gz" && p.stem().extension() == ".pbrt");
    return sceneExtension && std::filesystem::is_regular_file(p);
}

void refuseOptions(const OptionValues& v, const std::vector<std::string>& names,
                   const std::string& why) {
    for (const std::string& name : names)
        if (v.given(name)) throw InputError("--" + name + " " + why);
}

/// The scene of the scene mode, or nothing: the materials' mode. InputError for an input that
/// is neither a scene file nor a material, or a scene given with other inputs.
std::optional<std::string> sceneOf(const OptionValues& v) {
    const std::vector<std::string> inputs = v.texts("inputs");
    if (inputs.size() == 1 && isSceneFile(inputs[0])) {
        refuseOptions(v, kMaterialsOnly, "applies to materials, not to a scene");
        return inputs[0];
    }
    for (const std::string& in : inputs) {
        if (isSceneFile(in))
            throw InputError(in + ": a scene goes alone; give one scene or material names");
        if (!mayBeMaterial(in))
            throw InputError("\"" + in +
                             "\" is neither a scene file (.json, .pbrt, .xml) nor a material: "
                             "expected a metal or glass name (" +
                             knownMaterialNames() + ") or an n/k file (YAML or CSV)");
    }
    refuseOptions(v, kSceneOnly, "applies to a scene's renders, not to materials");
    return std::nullopt;
}

PolarisationInputs polarisationInputs(const OptionValues& v, const CommandContext& context,
                                      const std::string& scene) {
    PolarisationInputs in;
    in.scene = scene;
    in.spp = int(v.integer("spp").value_or(0));
    if (const auto seed = v.integer("seed")) in.overrides.seed = std::uint64_t(*seed);
    in.overrides.integrator = v.choice(render::kIntegratorNames, "integrator");
    in.dolpThreshold = *v.number("dolp-threshold");
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

PolarisationMaterialsInputs materialsInputs(const OptionValues& v) {
    PolarisationMaterialsInputs in;
    in.materials = v.texts("inputs");
    in.wavelengths.clear();
    for (const std::string& nm : v.texts("wavelengths"))
        in.wavelengths.push_back(std::stod(nm));
    return in;
}

Data flooredData(const FlooredStatistic& s, int spp) {
    const NoiseFloorReading reading = readAgainstFloor(s.value, s.floor, spp);
    Data d = Data::dict();
    d.set("value", s.value);
    d.set("noise_floor", s.floor);
    d.set("resolved", reading.resolved);
    d.set("other_seed", s.otherSeed);
    return d;
}

std::vector<double> asDoubles(const std::vector<float>& values) {
    return {values.begin(), values.end()};
}

Data materialsData(const OptionValues& v) {
    const PolarisationMaterialsResult r = runPolarisationMaterials(materialsInputs(v));
    Data out = Data::list();
    for (const PolarisationMaterial& m : r.materials) {
        Data curves = Data::list();
        for (const MuellerCurve& c : m.curves) {
            std::vector<double> mueller;
            for (const auto& matrix : c.mueller)
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j)
                        mueller.push_back(matrix(i, j));
            Data d = Data::dict();
            d.set("nm", c.nm);
            d.set("n", c.index.real());
            d.set("k", c.index.imag());
            d.set("mueller", Data::array(std::move(mueller), {c.mueller.size(), 4, 4}));
            d.set("rs", Data::array(c.rs));
            d.set("rp", Data::array(c.rp));
            d.set("diattenuation", Data::array(c.diattenuation));
            d.set("retardance", Data::array(c.retardance));
            d.set("principal_angle", c.principalAngle ? Data::number(*c.principalAngle) : Data());
            d.set("minimum_rp_angle", c.minimumRpAngle);
            curves.append(std::move(d));
        }
        Data d = Data::dict();
        d.set("material", m.stem);
        d.set("name", m.name);
        d.set("conductor", m.conductor);
        d.set("degrees", Data::array(r.degrees));
        d.set("wavelengths", std::move(curves));
        out.append(std::move(d));
    }
    return out;
}

Data polarisationData(const OptionValues& v, const CommandContext& context) {
    const std::optional<std::string> scene = sceneOf(v);
    if (!scene) return materialsData(v);
    const PolarisationResult r = runPolarisation(polarisationInputs(v, context, *scene));
    const int spp = r.polarised.spp;
    const std::vector<std::size_t> shape{std::size_t(r.height), std::size_t(r.width)};
    Data d = Data::dict();
    d.set("spp", spp);
    for (const auto& [prefix, a] :
         {std::pair<std::string, const AgainstPolarised*>{"", &r.spectral}, {"rgb_", &r.rgb}}) {
        d.set(prefix + "mean_relative_difference", flooredData(a->meanRelative, spp));
        d.set(prefix + "p95_relative_difference", flooredData(a->p95Relative, spp));
        d.set(prefix + "mean_delta_e", flooredData(a->meanDeltaE, spp));
        d.set(prefix + "p95_delta_e", flooredData(a->p95DeltaE, spp));
        d.set(prefix + "compared_pixels", static_cast<long long>(a->comparedPixels));
        // The relative difference map is NaN where both renders are black: None has no place in
        // an array, so those pixels are 0 here and `compared_pixels` counts the others.
        std::vector<double> relative = asDoubles(a->relative);
        for (double& x : relative)
            if (!std::isfinite(x)) x = 0;
        d.set(prefix + "relative_difference", Data::array(std::move(relative), shape));
        d.set(prefix + "delta_e", Data::array(asDoubles(a->ciede2000), shape));
    }
    d.set("dolp", Data::array(asDoubles(r.dolp), shape));
    d.set("aolp", Data::array(asDoubles(r.aolp), shape));
    d.set("mean_dolp", r.meanDolp);
    d.set("max_dolp", r.maxDolp);
    d.set("dolp_noise", r.dolpNoise);
    return d;
}

}  // namespace

CommandDecl polarisationDeclaration() {
    const PolarisationInputs defaults;
    const PolarisationMaterialsInputs materialDefaults;
    std::vector<std::string> wavelengths;
    for (const double nm : materialDefaults.wavelengths)
        wavelengths.push_back(formatText("%g", nm));
    CommandDecl c;
    c.name = "polarisation";
    c.help =
        "What ignoring polarisation costs: a scene in the polarised, spectral and RGB modes (their "
        "relative and CIEDE2000 differences against the noise floor, DoLP and AoLP maps), or "
        "materials' Mueller matrices of reflection against angle";
    c.returns =
        "for a scene a dict: spp; mean_relative_difference, p95_relative_difference, "
        "mean_delta_e, p95_delta_e (the spectral render against the polarised one; each value, "
        "noise_floor, resolved, other_seed: between the renders of the floor's seed); "
        "compared_pixels; the per-pixel relative_difference and delta_e; the same of the RGB "
        "render against the polarised one prefixed rgb_ (rgb_mean_relative_difference, ..., "
        "rgb_delta_e); the polarised render's dolp and aolp (degrees) as (H, W) arrays (0 where "
        "there is no light), mean_dolp, max_dolp, dolp_noise. Ctrl-C raises KeyboardInterrupt "
        "with .partial: {\"renders\": the finished renders (name, mode, integrator, seed, spp, "
        "rgb as an (H, W, 3) array)}. For materials a list, per "
        "material a dict: material, name, conductor, degrees (0 ... 90), wavelengths: per "
        "wavelength nm, n, k, mueller (angles x 4 x 4), rs, rp, diattenuation, retardance "
        "(degrees), principal_angle (None if M22 keeps its sign), minimum_rp_angle";
    c.options = {
        textListOption("inputs",
                       "A scene file (.json, .pbrt, .xml), or materials: metals (Au, Ag, Cu, "
                       "...), glasses (bk7, ...) or n/k files")
            .asPositional()
            .asRequired(),
        outputDirectoryOption(),
        numberListOption("wavelengths", "Materials: the wavelengths of the curves, in nm")
            .byDefault(wavelengths),
        integerOption("spp", "Scene: samples per pixel of every render (default: the scene's)", 1,
                      render::kMaxSppOverride),
        integerOption("seed", "Scene: seed of the compared renders (default: the scene's)", 0,
                      render::kMaxSeedOverride),
        nameOption("integrator", "Scene: light transport algorithm (overrides the scene's)",
                   render::kIntegratorNames),
        numberOption("dolp-threshold",
                     "Scene: the AoLP map shows pixels whose degree of linear polarisation is at "
                     "least this",
                     0.0, 1.0)
            .byDefault(defaults.dolpThreshold),
        threadsOption(),
        maxDepthOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        resumeOption(),
    };
    c.report = [](const OptionValues& v, const CommandContext& context) -> ReportWork {
        const std::optional<std::string> scene = sceneOf(v);
        if (!scene) {
            const PolarisationMaterialsInputs in = materialsInputs(v);
            return {[in](Report& report) {
                        writePolarisationMaterialsReport(runPolarisationMaterials(in), report);
                        report.finish();
                        return 0;
                    },
                    false};
        }
        PolarisationInputs in = polarisationInputs(v, context, *scene);
        in.resume = v.flag("resume");
        return {[in](Report& report) {
            PolarisationInputs run = in;
            run.keepDirectory = report.directory();
            writePolarisationReport(runPolarisation(run), report);
            report.finish();
            removeKeptRenders(report.directory());
            return 0;
        }};
    };
    c.data = polarisationData;
    return c;
}

}  // namespace lamina::experiments
