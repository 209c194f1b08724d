// The sums a film keeps beyond PixelSums, as named doubles per pixel, for shard files and
// merges: the polarised mode's Stokes sums of S1..S3 ("S1.Sum.R", ..., "S3.Splat.B") and the
// spectral film's ("S0.Sum.550,000000nm", ..., and "S0.Splat.<nm>nm" with a splat layer). The
// names depend only on what the film has, so a film given the same layers (enableStokes,
// enableSpectralFilm) reads its values back in the same order.
#pragma once

#include <string>
#include <vector>

#include "lamina/render/film.h"

namespace lamina::render {

/// The names of the film's layer sums, in the order of layerSums' values.
std::vector<std::string> layerSumNames(const Film& film);
/// Appends the layer sums of pixel (x, y) of the film's window to `out`.
void appendLayerSums(const Film& film, int x, int y, std::vector<double>& out);
/// Adds layer sums (in layerSumNames' order) to pixel (x, y) of the whole image.
void addLayerSums(Film& film, int x, int y, const double* values);

}  // namespace lamina::render
