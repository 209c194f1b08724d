// Provenance of a render, written into its EXR as "lamina:<key>" attributes: what made the
// image (version, git commit, command line, the hash of every input file) and every setting
// in effect after the command line's overrides, so that an image can be reproduced and two
// images can be told apart (`lamina convergence` refuses a reference correlated with its
// measured renders by reading these keys back).
#pragma once

#include <string>

#include "lamina/output/image_output.h"
#include "lamina/render/renderer.h"

namespace lamina::render {

/// What only the executable knows.
struct BuildInfo {
    std::string version;  ///< e.g. "0.1.0"
    std::string
        gitCommit;  ///< `git rev-parse HEAD` at configure time, "unknown" outside a checkout
};

/// FNV-1a 64 (hex) over every input file of the scene (SceneDesc::inputFiles: the JSON, then
/// meshes, textures, n/k tables, environment maps), each file's name length and bytes in turn:
/// changing any file the scene reads changes the hash.
std::string sceneHash(const SceneDesc& scene);

/// This process's command line, arguments separated by spaces ("unknown" where the platform
/// does not expose it).
std::string processCommandLine();

/// Every key of a render's EXR (docs/scene-format.md, "Image metadata").
ImageMetadata renderMetadata(const SceneDesc& scene, const RenderOptions& options,
                             const RenderResult& result, const BuildInfo& build);

}  // namespace lamina::render
