#include "lamina/experiments/command_options.h"

#include "lamina/render/render_limits.h"

namespace lamina::experiments {

OptionDecl sceneOption(std::string help) {
    return fileOption("scene", std::move(help)).asPositional().asRequired().existing();
}

OptionDecl outputDirectoryOption(std::string help) {
    return textOption("output", std::move(help))
        .shortFlag('o')
        .asRequired()
        .commandLineOnly("the report's directory: Python returns the results instead");
}

OptionDecl threadsOption() {
    return integerOption("threads", "Worker threads (default: all cores)", 1,
                         render::kMaxThreadsOverride);
}

OptionDecl maxDepthOption() {
    return integerOption("max-depth", "Maximum scattering events per path", 1,
                         render::kMaxDepthOverride);
}

OptionDecl resolutionOverrideOption() {
    return resolutionOption("resolution", "Image size WIDTHxHEIGHT (overrides)");
}

OptionDecl resumeOption() {
    return flagOption("resume",
                      "Continue the interrupted run in --output's directory: the renders it kept "
                      "(renders/) are used, not rendered again; refused if they were rendered "
                      "with other settings")
        .commandLineOnly(
            "Python keeps no files: an interrupted call's KeyboardInterrupt carries .partial, "
            "what was done");
}

void applyRenderOverrides(const OptionValues& values, render::RenderOptions& options) {
    options.threads = int(values.integer("threads").value_or(0));
    if (const auto depth = values.integer("max-depth")) options.maxDepth = int(*depth);
    if (const auto resolution = values.resolution("resolution")) options.resolution = resolution;
}

render::RenderOptions renderOptionsFrom(const OptionValues& values) {
    render::RenderOptions o;
    if (const auto mode = values.choice(render::kRenderModeNames, "mode")) o.mode = *mode;
    if (const auto spp = values.integer("spp")) o.spp = int(*spp);
    if (const auto seconds = values.number("time")) o.seconds = *seconds;
    if (const auto seed = values.integer("seed")) o.seed = std::uint64_t(*seed);
    o.sampler = values.choice(render::kSamplerNames, "sampler");
    o.lightSelection = values.choice(render::kLightSelectionNames, "light-selection");
    o.integrator = values.choice(render::kIntegratorNames, "integrator");
    o.mis = values.choice(render::kMisHeuristicNames, "mis");
    applyRenderOverrides(values, o);
    o.aovs = values.flag("aovs");
    for (const render::RenderAblation a : values.choices(render::kRenderAblationNames, "ablate"))
        render::applyRenderAblation(a, o.ablations);
    if (const auto bins = values.integer("spectral-film")) o.spectralBins = int(*bins);
    return o;
}

}  // namespace lamina::experiments
