#include "lamina/spectral/white_balance.h"

#include <glm/matrix.hpp>

namespace lamina {

Chromaticity daylightChromaticity(double kelvin) {
    const double t = kelvin * 1.4388 / 1.4380;
    const double t2 = t * t, t3 = t2 * t;
    const double x = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                               : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    return {x, -3.000 * x * x + 2.870 * x - 0.275};
}

Mat3<double> bradfordAdaptation(const Vec3d& sourceWhite, const Vec3d& targetWhite) {
    // Rows of the Bradford cone-response matrix (GLM matrices are column-major: transposed).
    const Mat3<double> m = glm::transpose(Mat3<double>(0.8951, 0.2664, -0.1614,  //
                                                       -0.7502, 1.7135, 0.0367,  //
                                                       0.0389, -0.0685, 1.0296));
    const Vec3d s = m * (sourceWhite / sourceWhite.y), d = m * (targetWhite / targetWhite.y);
    Mat3<double> scale(1.0);
    for (int i = 0; i < 3; ++i)
        scale[i][i] = d[i] / s[i];
    return glm::inverse(m) * scale * m;
}

}  // namespace lamina
