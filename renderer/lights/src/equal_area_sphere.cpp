#include "lamina/lights/equal_area_sphere.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/math.h"

namespace lamina::render {

// Clarberg 2008, section 3: in the first quadrant of [-1, 1]^2 the distance r from the corner
// of the diamond's edge u + v = 1 (r = u + v inside it) sets the polar angle through
// z = 1 - r^2 (equal area: the solid angle within r is 2 pi (1 - z) = 2 pi r^2, the square's
// area within r times 4 pi / 4), and the position along that edge sets phi linearly in
// [0, pi / 2]. The lower hemisphere is the upper one folded outwards over the diamond's edges.
Vec3d equalAreaSquareToSphere(const Vec2d& uv) {
    const double u = 2 * uv.x - 1, v = 2 * uv.y - 1;
    const double au = std::abs(u), av = std::abs(v);
    const double signedDistance = 1 - (au + av);  // > 0 inside the diamond: the upper half
    const double r = 1 - std::abs(signedDistance);
    const double phi =
        r == 0 ? kPi<double> / 4 : (av - au) / r * (kPi<double> / 4) + kPi<double> / 4;
    const double z = std::copysign(1 - r * r, signedDistance);
    const double sinTheta = r * std::sqrt(std::max(0.0, 2 - r * r));
    return {std::copysign(std::cos(phi), u) * sinTheta, std::copysign(std::sin(phi), v) * sinTheta,
            z};
}

Vec2d equalAreaSphereToSquare(const Vec3d& w) {
    const double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
    // The inverse of z = 1 - r^2 and of phi = pi / 4 (1 + (v - u) / r), in the first quadrant.
    const double r = std::sqrt(std::max(0.0, 1 - az));
    const double phi = std::atan2(ay, ax);  // [0, pi / 2]
    const double t = phi / (kPi<double> / 2);
    double v = t * r, u = r - v;
    if (w.z < 0) {  // fold the lower hemisphere outwards over the diamond's edge
        std::swap(u, v);
        u = 1 - u;
        v = 1 - v;
    }
    u = std::copysign(u, w.x);
    v = std::copysign(v, w.y);
    return {std::clamp(0.5 * (u + 1), 0.0, 1.0), std::clamp(0.5 * (v + 1), 0.0, 1.0)};
}

}  // namespace lamina::render
