// Linear RGB colour spaces defined by their primaries and white point, with the XYZ <-> RGB
// matrices derived from them (SMPTE RP 177-1993, the standard derivation): the columns of
// RGB->XYZ are the primaries' XYZ, scaled so that RGB (1, 1, 1) maps to the white point.
#pragma once

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina {

struct Chromaticity {
    double x, y;
    Vec3d toXyz(double Y = 1.0) const { return {x * Y / y, Y, (1.0 - x - y) * Y / y}; }
};

class RgbColorSpace {
  public:
    RgbColorSpace(Chromaticity r, Chromaticity g, Chromaticity b, Vec3d whiteXyz);

    /// Linear Rec.709 / sRGB primaries (ITU-R BT.709-6: R (0.64, 0.33), G (0.30, 0.60),
    /// B (0.15, 0.06)) with the white point of the CIE D65 table integrated against the CIE
    /// 1931 CMFs, so that the D65 spectrum maps to RGB (1, 1, 1) exactly.
    static const RgbColorSpace& rec709();

    Vec3d toRgb(const Vec3d& xyz) const { return xyzToRgb_ * xyz; }
    Vec3d toXyz(const Vec3d& rgb) const { return rgbToXyz_ * rgb; }
    const Mat3<double>& xyzToRgb() const { return xyzToRgb_; }
    const Mat3<double>& rgbToXyz() const { return rgbToXyz_; }
    const Vec3d& whiteXyz() const { return white_; }
    Chromaticity red() const { return r_; }
    Chromaticity green() const { return g_; }
    Chromaticity blue() const { return b_; }

  private:
    Chromaticity r_, g_, b_;
    Vec3d white_;
    Mat3<double> rgbToXyz_, xyzToRgb_;
};

/// XYZ of the D65 table, normalised to Y = 1.
Vec3d d65WhiteXyz();

}  // namespace lamina
