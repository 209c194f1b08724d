#include "lamina/spectral/color_space.h"

#include <glm/matrix.hpp>

#include "lamina/spectral/cie.h"

namespace lamina {

RgbColorSpace::RgbColorSpace(Chromaticity r, Chromaticity g, Chromaticity b, Vec3d whiteXyz)
    : r_(r), g_(g), b_(b), white_(whiteXyz) {
    // Columns: the XYZ of each primary at Y = 1 (GLM matrices are column-major).
    const Mat3<double> primaries(r.toXyz(), g.toXyz(), b.toXyz());
    // Scale each primary so that their sum is the white point.
    const Vec3d scale = glm::inverse(primaries) * whiteXyz;
    rgbToXyz_ =
        Mat3<double>(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
    xyzToRgb_ = glm::inverse(rgbToXyz_);
}

Vec3d d65WhiteXyz() {
    static const Vec3d white = [] {
        const TabulatedCurve* d65 = findCieIlluminant("D65");
        const Vec3d xyz = integrateAgainstCmf([d65](double nm) { return (*d65)(nm); });
        return xyz / xyz.y;
    }();
    return white;
}

const RgbColorSpace& RgbColorSpace::rec709() {
    static const RgbColorSpace space({0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, d65WhiteXyz());
    return space;
}

}  // namespace lamina
