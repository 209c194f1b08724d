// Options that several commands declare alike (the scene, the report directory, the render
// overrides), each with one help text, and the render options read from declared values: what
// `lamina render` and lamina.render override, and what every experiment's renders take.
#pragma once

#include <string>

#include "lamina/experiments/command_declaration.h"
#include "lamina/render/renderer.h"

namespace lamina::experiments {

/// The scene file: a required positional argument.
OptionDecl sceneOption(std::string help = "Scene file");
/// -o, --output: the directory of an experiment's report (the command line only).
OptionDecl outputDirectoryOption(std::string help = "Output directory");
/// --threads, --max-depth, --resolution: the overrides of every command that renders.
OptionDecl threadsOption();
OptionDecl maxDepthOption();
OptionDecl resolutionOverrideOption();

/// --resume: take back the renders an interrupted run kept in --output's directory
/// (kept_renders.h; the command line only: Python keeps no files).
OptionDecl resumeOption();

/// --threads, --max-depth and --resolution, as given, into `options`.
void applyRenderOverrides(const OptionValues& values, render::RenderOptions& options);

/// `lamina render`'s options and lamina.render's keywords as the render's options (the
/// command line's own, --samples, --crop and --strategies, are the command line's to read).
render::RenderOptions renderOptionsFrom(const OptionValues& values);

}  // namespace lamina::experiments
