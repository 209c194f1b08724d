// White balance: the chromaticity of CIE daylight at a colour temperature, and the Bradford
// chromatic adaptation from one white to another. A camera's white balance at T kelvin maps
// the white of daylight at T to the image's white, as pbrt-v4's sensor does.
#pragma once

#include "lamina/core/vector.h"
#include "lamina/spectral/color_space.h"

namespace lamina {

/// The CIE daylight locus (CIE 15:2004, eq. 3.3 and 3.4) at `kelvin` in [4000, 25000], the
/// temperature taken on the scale of the D illuminants' names (times 1.4388 / 1.4380, the
/// revision of the radiation constant c2 that makes "6500 K" D65's 6504 K).
Chromaticity daylightChromaticity(double kelvin);

/// The linear map of CIE XYZ that takes `sourceWhite` to `targetWhite` (each normalised to
/// Y = 1), scaling the cone responses of the Bradford transform (Lam 1985; the von Kries
/// rule on its sharpened cone space): M^-1 diag(target / source) M.
Mat3<double> bradfordAdaptation(const Vec3d& sourceWhite, const Vec3d& targetWhite);

}  // namespace lamina
