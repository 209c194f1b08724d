// RGL material files (.bsdf, the measured BSDFs of Dupuy and Jakob 2018 that pbrt-v4's and
// Mitsuba 3's `measured` materials read) into the table of lamina's `measured` material
// (lamina/bsdf/measured_table.h, which says what each field means).
//
// The file is a tensor file, every number little-endian:
//   "tensor_file\0" (12 bytes), version (2 bytes: 1, 0), field count (uint32), then per field
//   its name length (uint16), name, rank (uint16), type (uint8: 1 uint8, 2 int8, 3 uint16,
//   4 int16, 5 uint32, 6 int32, 7 uint64, 8 int64, 9 float16, 10 float32, 11 float64), offset
//   of its data from the start of the file (uint64) and its shape (rank uint64, slowest first).
// The fields an RGL file has: theta_i, phi_i, ndf, sigma, vndf, luminance, and spectra with
// wavelengths or rgb (all float32), description (uint8 text) and jacobian (one uint8). Other
// fields are ignored. Every size and offset is checked against the file's length before a
// byte is copied, so a hostile header allocates nothing; any problem is one InputError line
// "FILE: what was expected" (naming the field).
#pragma once

#include <cstdint>
#include <filesystem>

#include "lamina/bsdf/material.h"
#include "lamina/bsdf/measured_table.h"
#include "lamina/core/input_file.h"

namespace lamina::render {

/// The largest RGL file read (the database's are some 1 to 30 MiB).
inline constexpr std::uintmax_t kMaxRglFileBytes = 1024 * kMiB;

/// The table of the RGL file at `path`.
MeasuredBsdfTable readRglBsdfFile(const std::filesystem::path& path);

/// Reads the file of every `measured` material in `m` and in the materials nested in it whose
/// table is not read yet. A file already read (the same path, size and time) is shared.
void loadMeasuredTables(const MaterialDesc& m);

}  // namespace lamina::render
