// `lamina render` and lamina.render: the render's overrides are both front ends'; the files
// the command line writes beside the image are its own, and Python returns the image instead.
#include "declarations.h"
#include "lamina/experiments/command_options.h"
#include "lamina/render/render_limits.h"

namespace lamina::experiments {

CommandDecl renderDeclaration() {
    CommandDecl c;
    c.name = "render";
    c.help = "Render a scene file to OpenEXR";
    c.returns = "an Image: rgb, aovs, metadata, save(path)";
    c.options = {
        sceneOption("Scene file (JSON, see docs/scene-format.md)")
            .differsInPython("Python also takes the scene as a dict in the scene format"),
        textOption("output", "Output EXR (default: the scene's name in the current directory)")
            .shortFlag('o')
            .commandLineOnly("Python returns the Image; Image.save(path) writes the EXR"),
        nameOption("mode", "Render mode", render::kRenderModeNames)
            .byDefault(std::string(render::kRenderModeNames.name(render::RenderModeKind::Rgb))),
        nameOption("integrator", "Light transport algorithm (overrides the scene's)",
                   render::kIntegratorNames),
        nameOption("mis", "BDPT's MIS heuristic (overrides the scene's)",
                   render::kMisHeuristicNames),
        fileOption("reference", "Reference image for --error-log")
            .existing()
            .needing("error-log")
            .commandLineOnly("the reference of --error-log; lamina.convergence measures error "
                             "against time in Python"),
        textOption("error-log",
                   "CSV of seconds, spp, MSE, relMSE, MAE against --reference after every pass")
            .needing("reference")
            .commandLineOnly("a CSV file; lamina.convergence returns error against time"),
        textOption("strategies",
                   "bdpt: also write one EXR per (s, t) strategy, MIS-weighted and unweighted, "
                   "path depth <= 4, into this directory")
            .commandLineOnly("a directory of EXR files, one per strategy"),
        integerOption("spp", "Samples per pixel (overrides the scene's)", 1,
                      render::kMaxSppOverride),
        positiveOption("time", "Render progressive passes for this many seconds", "seconds")
            .excluding("spp"),
        textOption("samples",
                   "FIRST:COUNT: render sample indices [FIRST, FIRST+COUNT) of every pixel "
                   "into a shard EXR for `lamina merge` (with --time: at most COUNT)")
            .excluding("spp")
            .commandLineOnly("a shard EXR for `lamina merge`, a file"),
        textOption("crop",
                   "X0,X1,Y0,Y1: render pixels [X0,X1) x [Y0,Y1) of the film into a shard EXR "
                   "for `lamina merge`")
            .commandLineOnly("a shard EXR for `lamina merge`, a file"),
        integerOption("seed", "Random seed (overrides the scene's)", 0, render::kMaxSeedOverride),
        threadsOption(),
        resolutionOverrideOption().differsInPython("Python also takes (width, height)"),
        maxDepthOption(),
        nameOption("sampler", "Sample generator", render::kSamplerNames),
        nameOption("light-selection",
                   "How next-event estimation picks a light (overrides the scene's)",
                   render::kLightSelectionNames),
        flagOption("preview", "Also write a PNG preview beside the EXR")
            .commandLineOnly("Image.save(\"NAME.png\") writes the preview"),
        numberOption("exposure", "Exposure of the preview in stops")
            .byDefault(0.0)
            .commandLineOnly("of the preview: Image.save(path, exposure) takes it"),
        nameListOption("ablate",
                       "Render with a worse estimator on purpose: media-spectral-mis weights "
                       "every channel of a path through media by its hero channel's density "
                       "alone, without the spectral MIS over the channels (docs/media.md)",
                       render::kRenderAblationNames, "ablation"),
        flagOption("aovs",
                   "Add AOV layers: Albedo.RGB, N.XYZ (shading normal), Z (depth), Variance.Y"),
        integerOption("spectral-film",
                      "Also keep N bins of spectral radiance over 360-830 nm per pixel: EXR "
                      "layers S0.<nm>nm (S0..S3 in polarised mode), the spectral OpenEXR layout "
                      "(spectral and polarised modes)",
                      1, render::kMaxSpectralFilmBins),
        flagOption("quiet", "No progress or summary on stderr")
            .shortFlag('q')
            .commandLineOnly("Python prints nothing; its progress report is progress="),
        callbackOption("progress",
                       "Called after every pass with a dict of fraction, seconds, passes and spp")
            .pythonOnly("the command line draws a progress bar on stderr instead"),
    };
    return c;
}

}  // namespace lamina::experiments
