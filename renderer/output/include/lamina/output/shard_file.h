// Shard files: the EXR a render of a sample range or a crop writes (`render --samples
// FIRST:COUNT`, `--crop X0,X1,Y0,Y1`), carrying what an exact merge needs. Beside R, G, B (the
// shard's own image, for a look) it holds every per-pixel sum of the film (PixelSums: weighted
// sums per channel, weight sum, sample count, luminance moments, AOV sums, the splat layer's
// sums and its count; a polarised render's Stokes sums of S1..S3 and the spectral film's sums
// too, shard_layers.h), each double stored as two
// floats (the value rounded to float, then the rounding error; 48 bits together, so the merge is
// exact up to the order of summation), and metadata: the scene hash, the settings that decide a
// pixel's numbers, the sample range and the crop (also the EXR data window).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "lamina/output/image_output.h"
#include "lamina/render/film.h"
#include "lamina/render/renderer.h"

namespace lamina::render {

/// One line of every setting that changes a pixel's numbers ("mode=rgb integrator=path ..."):
/// shards merge only if theirs are equal.
std::string shardSettings(const SceneDesc& scene, const RenderOptions& options,
                          const RenderResult& result);
/// The same line before the render: the one `renderScene(scene, options)` will have.
std::string shardSettings(const SceneDesc& scene, const RenderOptions& options);

/// Adds the shard keys to a render's metadata (docs/distributed.md, "Shard files").
void addShardMetadata(ImageMetadata& metadata, const SceneDesc& scene, const RenderOptions& options,
                      const RenderResult& result);

void writeShardExr(const std::filesystem::path& path, const Film& film,
                   const ImageMetadata& metadata);

struct ShardFile {
    std::filesystem::path path;
    std::string sceneHash;
    std::string settings;
    int fullWidth = 0, fullHeight = 0;
    PixelBounds crop;
    SampleRange requested;  ///< the range the shard was asked for
    int samplesDone = 0;    ///< it holds [requested.first, requested.first + samplesDone)
    bool partial = false;   ///< interrupted before the end of its range
    double seconds = 0;
    ImageMetadata metadata;      ///< every lamina: attribute
    std::unique_ptr<Film> film;  ///< the sums, in a film of the crop's window
};

/// Reads a shard; InputError naming the file if it is not one or is damaged.
ShardFile readShardExr(const std::filesystem::path& path);

/// Adds the sums of `earlier`, a shard of the same settings and window, to `film`: a shard
/// restarted after an interruption renders the rest of its range and adds what it had.
/// InputError naming the file if the windows differ.
void addShardSums(Film& film, const ShardFile& earlier);

/// Adds every sum of `other`'s window (PixelSums, the Stokes and spectral film's sums, where
/// `film` has those layers too) to the same pixels of `film`.
void addFilmSums(Film& film, const Film& other);

}  // namespace lamina::render
