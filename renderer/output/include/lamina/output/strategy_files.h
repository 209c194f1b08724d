// BDPT's strategy images as files (`lamina render --strategies DIR`): per (s, t) strategy
// s<S>_t<T>_weighted.exr (its MIS-weighted share of the image) and s<S>_t<T>_unweighted.exr
// (what the strategy alone estimates), each with the render's metadata and the strategy's
// s, t and mis_weighted.
#pragma once

#include <filesystem>

#include "lamina/image/image_io.h"
#include "lamina/integrators/strategy_images.h"
#include "lamina/render/film.h"

namespace lamina::render {

/// `like`: the render's film (its colour space); `spp`: the samples per pixel rendered (the
/// splat part is divided by the number of particles, width x height x spp).
void writeStrategyImages(const std::filesystem::path& directory, const StrategyImages& images,
                         const Film& like, int spp, const ImageMetadata& metadata);

}  // namespace lamina::render
