// Grid files of other renderers that grid media read (docs/media.md, "Grid media"):
// Mitsuba's binary volume (.vol) and NanoVDB (.nvdb). Both are checked before anything is
// allocated from their headers (sizes against the limits of grid_file.h and the file's length);
// a bad file is one InputError line naming it.
#pragma once

#include <filesystem>
#include <string>

#include "lamina/core/vector.h"
#include "lamina/scene/density_grid.h"

namespace lamina::render {

/// True when the file starts with Mitsuba's "VOL" magic.
bool isMitsubaVolume(const std::filesystem::path& path);

/// Mitsuba's volume format (Mitsuba 3's gridvolume documentation): the bytes 'V', 'O', 'L', 3;
/// then little-endian int32 encoding (1: float32), xres, yres, zres, channels (1 or 3 read
/// here); six float32 (the bounding box xmin ymin zmin xmax ymax zmax); then the values,
/// data[((z yres + y) xres + x) channels + c]. Values must be finite and >= 0.
struct MitsubaVolume {
    DensityGrid grid;
    Vec3f boxMin, boxMax;  ///< the file's bounding box (Mitsuba 3 uses it with use_grid_bbox)
};
MitsubaVolume readMitsubaVolume(const std::filesystem::path& path);

/// True when the file starts with NanoVDB's magic number.
bool isNanoVdbFile(const std::filesystem::path& path);

/// A float grid of a NanoVDB file, densified over its active voxels' index bounding box with a
/// ring of the grid's background value around it. Voxel (i, j, k)'s value sits at index
/// coordinates (i, j, k) (NanoVDB's trilinear sampler's convention), so the densified grid
/// spans index space [min - 1.5, max + 1.5] and `indexToWorld` (the grid's affine map, rows of
/// a 3 x 4 matrix) places it in the file's world space.
struct NanoVdbGrid {
    DensityGrid grid;
    Vec3d indexMin, indexMax;  ///< the densified box in index space
    glm::dmat4 indexToWorld{1.0};
};
/// The grid named `name`; with `optional`, a file without it gives a grid of 0 values.
NanoVdbGrid readNanoVdbFile(const std::filesystem::path& path, const std::string& name);
/// Whether this build reads NanoVDB files (the header-only library was found).
bool readsNanoVdb();

}  // namespace lamina::render
