// The polarised mode's Stokes layers: from a camera path's Mueller matrix to the Stokes vector
// of the image frame (docs/polarisation.md, "Stokes images").
#include <cmath>

#include "lamina/core/math.h"
#include "lamina/render/render_mode.h"

namespace lamina::render {

std::array<PolarisedSpectrum::Element, 4> RenderMode<PolarisedSpectrum>::imageStokes(
    const Spectrum& L, const Vec3f& rayDirection, const Vec3f& imageRight) const {
    // The light travels towards the lens, against the camera ray; the path's matrices end in
    // the canonical frame of that direction (polarised_bxdf.h).
    const Vec3f d = -rayDirection;
    std::array<Element, 4> s{L.m[0][0], L.m[1][0], L.m[2][0], L.m[3][0]};
    const Vec3f right = imageRight - glm::dot(imageRight, d) * d;
    // A ray along the image's right (a field of view near 180 degrees) has no image frame to
    // speak of: it keeps the canonical one.
    if (glm::dot(right, right) > 1e-12f) {
        const DoubledTurn<float> turn =
            doubledFrameTurn(StokesFrame<float>{d, stokesAxis(d)}, right);
        const Element s1 = s[1] * turn.c + s[2] * turn.s, s2 = s[2] * turn.c - s[1] * turn.s;
        s[1] = s1;
        s[2] = s2;
    }
    if (analyserDegrees_) {
        const MuellerMatrix<float> a =
            linearPolariser(float(*analyserDegrees_ * kPi<double> / 180.0));
        std::array<Element, 4> out;
        for (int i = 0; i < 4; ++i)
            out[std::size_t(i)] =
                s[0] * a.m[i][0] + s[1] * a.m[i][1] + s[2] * a.m[i][2] + s[3] * a.m[i][3];
        s = out;
    }
    return s;
}

}  // namespace lamina::render
