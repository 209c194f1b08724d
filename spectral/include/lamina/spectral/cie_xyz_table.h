// The CIE 1931 colour matching functions divided by the integral of y-bar, resampled at
// every nanometre in float (ResampledSpectrum): spectral mode's film converts a path's four
// wavelengths to XYZ with them. The functions are piecewise linear on 5 nm knots from 360 nm
// (colord-data), so the 1 nm samples reproduce them to float rounding, and one position
// serves all three.
#pragma once

#include "lamina/spectral/resampled_spectrum.h"

namespace lamina {

struct CieXyzTable {
    ResampledSpectrum x, y, z;

    /// x-bar, y-bar, z-bar / integral of y-bar: a constant spectrum 1 integrates to Y = 1.
    static const CieXyzTable& normalized();
};

}  // namespace lamina
