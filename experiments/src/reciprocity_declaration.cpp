// `lamina reciprocity` and lamina.reciprocity (reciprocity.h): the options, the inputs read
// from them, the report (exit status 2 when a pair disagrees), and the result as data.
#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/reciprocity.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

namespace {

ReciprocityInputs reciprocityInputs(const OptionValues& v, const CommandContext& context) {
    ReciprocityInputs in;
    in.scene = *v.text("scene");
    in.integrators = v.choices(render::kIntegratorNames, "integrators");
    in.mode = *v.choice(render::kRenderModeNames, "mode");
    in.spp = int(*v.integer("spp"));
    in.batches = int(*v.integer("batches"));
    in.seed = std::uint64_t(*v.integer("seed"));
    in.test.alpha = *v.number("alpha");
    in.test.blockSize = int(*v.integer("block"));
    in.reference = v.text("reference").value_or("");
    in.ablations = v.choices(kAblationNames, "ablate");
    applyRenderOverrides(v, in.overrides);
    in.progress = context.progress;
    return in;
}

ReportWork reciprocityReport(const OptionValues& v, const CommandContext& context) {
    ReciprocityInputs in = reciprocityInputs(v, context);
    in.resume = v.flag("resume");
    return {[in](Report& report) {
        ReciprocityInputs run = in;
        run.keepDirectory = report.directory();
        const ReciprocityResult result = runReciprocity(run);
        writeReciprocityReport(result, report);
        report.finish();
        removeKeptRenders(report.directory());
        return result.allAgree ? 0 : 2;
    }};
}

Data reciprocityData(const OptionValues& v, const CommandContext& context) {
    const ReciprocityResult r = runReciprocity(reciprocityInputs(v, context));
    const double alpha = r.inputs.test.alpha;
    Data pairs = Data::list();
    for (const auto& p : r.pairs) {
        Data d = Data::dict();
        d.set("a", p.nameA);
        d.set("b", p.nameB);
        d.set("agree", p.agree);
        d.set("relative_difference", p.result.relativeDifference);
        d.set("standard_error", p.result.standardError);
        d.set("mean_a", p.result.meanA);
        d.set("mean_b", p.result.meanB);
        d.set("pixel_rejection_rate", p.result.pixelRejectionRate());
        d.set("block_rejection_rate", p.result.blockRejectionRate());
        d.set("block_rejection_p_value", p.result.blockRejectionPValue(alpha));
        d.set("pixel_test_trustworthy", p.pixelTest.trustworthy);
        pairs.append(std::move(d));
    }
    Data materials = Data::list();
    for (const auto& m : r.materials) {
        Data d = Data::dict();
        d.set("material", m.material);
        d.set("mode", render::kRenderModeNames.name(m.mode));
        d.set("max_reciprocity_error", m.check.maxReciprocityError);
        d.set("max_adjoint_error", m.check.maxAdjointError);
        d.set("pairs", m.check.pairs);
        materials.append(std::move(d));
    }
    Data out = Data::dict();
    out.set("pairs", std::move(pairs));
    out.set("materials", std::move(materials));
    out.set("agree", r.allAgree);
    return out;
}

}  // namespace

CommandDecl reciprocityDeclaration() {
    const ReciprocityInputs defaults;
    CommandDecl c;
    c.name = "reciprocity";
    c.help =
        "Test whether path, light and bdpt converge to the same image (per-pixel and blockwise "
        "t-tests) and whether every BSDF is reciprocal; exit status 2 if they disagree";
    c.returns =
        "a dict: pairs (per pair of integrators: agree, relative_difference, standard_error, the "
        "means, the rejection rates and the block test's p-value), materials (the largest "
        "reciprocity and adjoint errors of every material) and agree, the verdict. Ctrl-C "
        "raises KeyboardInterrupt with .partial: {\"renders\": the finished batch renders "
        "(name, mode, integrator, seed, spp, rgb as an (H, W, 3) array)}";
    c.options = {
        sceneOption(),
        outputDirectoryOption("Directory for the images and t-statistic maps"),
        nameListOption("integrators", "Comma-separated list", render::kIntegratorNames,
                       "integrator")
            .byDefault(namesOf(render::kIntegratorNames, defaults.integrators)),
        nameOption("mode", "Render mode", render::kRenderModeNames)
            .byDefault(std::string(render::kRenderModeNames.name(defaults.mode))),
        integerOption("spp", "Samples per pixel per integrator (over all batches)", 2,
                      render::kMaxSppOverride)
            .byDefault(defaults.spp),
        integerOption("batches",
                      "Independent batches per integrator (the variance estimate's sample size)", 2,
                      4096)
            .byDefault(defaults.batches),
        integerOption("seed", "Base seed", 0, render::kMaxSeedOverride)
            .byDefault(static_cast<long long>(defaults.seed)),
        numberOption("alpha", "Significance level of each test", 1e-6, 0.5)
            .byDefault(defaults.test.alpha),
        integerOption("block", "Block size of the blockwise test", 1, 256)
            .byDefault(defaults.test.blockSize)
            .spelledInPython("block_size", "the Python keyword since the first release"),
        fileOption("reference", "Also test each integrator against this EXR").existing(),
        threadsOption(),
        maxDepthOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        nameListOption("ablate",
                       "Reproduce a known bug on purpose: adjoint-correction (drop the "
                       "shading-normal factor on light paths), transport-mode (radiance's "
                       "1/eta^2 on light paths), swapped-directions (f(wi, wo) at light-path "
                       "connections)",
                       kAblationNames, ""),
        resumeOption(),
    };
    c.report = reciprocityReport;
    c.data = reciprocityData;
    return c;
}

}  // namespace lamina::experiments
