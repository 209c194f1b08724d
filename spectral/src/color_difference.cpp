#include "lamina/spectral/color_difference.h"

#include <cmath>

#include "lamina/core/math.h"
#include "lamina/spectral/color_space.h"

namespace lamina {

namespace {

double labF(double t) {
    // CIE 15:2004 eq. 8.3: the cube root, with a linear segment near black.
    constexpr double kDelta = 6.0 / 29.0;
    return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0;
}

double degrees(double r) {
    return r * 180.0 / kPi<double>;
}
double toRadians(double d) {
    return d * kPi<double> / 180.0;
}

}  // namespace

Vec3d xyzToLab(const Vec3d& xyz, const Vec3d& white) {
    const double fx = labF(xyz.x / white.x), fy = labF(xyz.y / white.y), fz = labF(xyz.z / white.z);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double ciede2000(const Vec3d& lab1, const Vec3d& lab2) {
    const double L1 = lab1.x, a1 = lab1.y, b1 = lab1.z;
    const double L2 = lab2.x, a2 = lab2.y, b2 = lab2.z;
    // Sharma et al. eq. 2-5: a' rescaled by G, which depends on the mean chroma.
    const double Cab = 0.5 * (std::hypot(a1, b1) + std::hypot(a2, b2));
    const double Cab7 = std::pow(Cab, 7);
    const double G = 0.5 * (1 - std::sqrt(Cab7 / (Cab7 + std::pow(25.0, 7))));
    const double ap1 = (1 + G) * a1, ap2 = (1 + G) * a2;
    const double Cp1 = std::hypot(ap1, b1), Cp2 = std::hypot(ap2, b2);
    auto hue = [](double b, double ap) {
        if (b == 0 && ap == 0) return 0.0;
        double h = degrees(std::atan2(b, ap));
        return h < 0 ? h + 360 : h;
    };
    const double hp1 = hue(b1, ap1), hp2 = hue(b2, ap2);
    // Eq. 8-10: the differences.
    const double dLp = L2 - L1, dCp = Cp2 - Cp1;
    double dhp = 0;
    if (Cp1 * Cp2 != 0) {
        dhp = hp2 - hp1;
        if (dhp > 180)
            dhp -= 360;
        else if (dhp < -180)
            dhp += 360;
    }
    const double dHp = 2 * std::sqrt(Cp1 * Cp2) * std::sin(toRadians(dhp / 2));
    // Eq. 12-22: the weighting functions.
    const double Lbp = 0.5 * (L1 + L2), Cbp = 0.5 * (Cp1 + Cp2);
    double hbp = hp1 + hp2;
    if (Cp1 * Cp2 != 0) {
        if (std::abs(hp1 - hp2) <= 180)
            hbp *= 0.5;
        else
            hbp = hp1 + hp2 < 360 ? 0.5 * (hbp + 360) : 0.5 * (hbp - 360);
    }
    const double T = 1 - 0.17 * std::cos(toRadians(hbp - 30)) +
                     0.24 * std::cos(toRadians(2 * hbp)) + 0.32 * std::cos(toRadians(3 * hbp + 6)) -
                     0.20 * std::cos(toRadians(4 * hbp - 63));
    const double dTheta = 30 * std::exp(-sqr((hbp - 275) / 25));
    const double Cbp7 = std::pow(Cbp, 7);
    const double Rc = 2 * std::sqrt(Cbp7 / (Cbp7 + std::pow(25.0, 7)));
    const double Sl = 1 + 0.015 * sqr(Lbp - 50) / std::sqrt(20 + sqr(Lbp - 50));
    const double Sc = 1 + 0.045 * Cbp;
    const double Sh = 1 + 0.015 * Cbp * T;
    const double Rt = -std::sin(toRadians(2 * dTheta)) * Rc;
    const double l = dLp / Sl, c = dCp / Sc, h = dHp / Sh;
    return std::sqrt(l * l + c * c + h * h + Rt * c * h);
}

double ciede2000Rec709(const Rgb<double>& a, const Rgb<double>& b) {
    const RgbColorSpace& cs = RgbColorSpace::rec709();
    const Vec3d white = cs.toXyz(Vec3d(1.0));
    return ciede2000(xyzToLab(cs.toXyz(Vec3d(a[0], a[1], a[2])), white),
                     xyzToLab(cs.toXyz(Vec3d(b[0], b[1], b[2])), white));
}

}  // namespace lamina
