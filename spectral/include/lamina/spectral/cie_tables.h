// The raw CIE tables generated at build time from Debian's colord-data (5 nm spacing for the
// colour matching functions; 1 or 5 nm for the illuminants). Use cie.h for lookups.
#pragma once

#include <span>

#include "lamina/spectral/tabulated_curve.h"

namespace lamina::cie_data {

extern const TabulatedCurve kCmfX;  ///< CIE 1931 2-degree x-bar, 360-830 nm
extern const TabulatedCurve kCmfY;  ///< y-bar
extern const TabulatedCurve kCmfZ;  ///< z-bar
/// CIE standard illuminants by name ("A", "D65", "E", "F1", ...), relative spectral power.
extern const std::span<const NamedCurve> kIlluminantList;

}  // namespace lamina::cie_data
