// Perceptual colour differences: CIE 1976 L*a*b* and the CIEDE2000 difference (CIE
// publication 142-2001), as the experiments report them (a difference of about 1 is just
// noticeable side by side).
#pragma once

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina {

/// L*a*b* of an XYZ colour relative to a reference white (CIE 15:2004, section 8.2.1).
Vec3d xyzToLab(const Vec3d& xyz, const Vec3d& whiteXyz);

/// The CIEDE2000 difference of two L*a*b* colours with kL = kC = kH = 1, following the
/// equations as written out by Sharma, Wu and Dalal 2005, "The CIEDE2000 Color-Difference
/// Formula: Implementation Notes, Supplementary Test Data, and Mathematical Observations".
double ciede2000(const Vec3d& lab1, const Vec3d& lab2);

/// CIEDE2000 between two linear Rec.709 colours, white RGB (1, 1, 1) being L* = 100 (values
/// above 1 are brighter than the white and still compared).
double ciede2000Rec709(const Rgb<double>& a, const Rgb<double>& b);

}  // namespace lamina
