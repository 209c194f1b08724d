// The measured n, k tables of the named metals (spectral/data/nk, compiled in by the build:
// spectral/cmake/GenerateMeasuredMetals.cmake), for namedIor (ior_spectrum.cpp).
#pragma once

#include <span>

namespace lamina {

struct MeasuredNk {
    double nm, n, k;
};

struct MeasuredMetal {
    const char* metal;   ///< its chemical symbol, the name scenes use ("Cu")
    const char* source;  ///< the measurement, as the data file names it ("JohnsonChristy1972")
    std::span<const MeasuredNk> samples;  ///< 360-830 nm every 5 nm
};

/// Every measured metal, by symbol.
std::span<const MeasuredMetal> measuredMetals();

}  // namespace lamina
