#include "lamina/spectral/rgb_to_spectrum_fit.h"

#include <cmath>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"

namespace lamina {

namespace {

constexpr double kWidth = kLambdaMax - kLambdaMin;

// CIE 1976 L*a*b* (CIE 15:2004, section 8.2.1) relative to the D65 white, and its Jacobian.
constexpr double kDelta = 6.0 / 29.0;

double labF(double t) {
    return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0;
}
double labFDerivative(double t) {
    return t > kDelta * kDelta * kDelta ? 1.0 / (3.0 * std::cbrt(t * t))
                                        : 1.0 / (3 * kDelta * kDelta);
}

Vec3d toLab(const Vec3d& xyz, const Vec3d& white) {
    const double fx = labF(xyz.x / white.x), fy = labF(xyz.y / white.y), fz = labF(xyz.z / white.z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// d(L, a, b) / d(X, Y, Z) as rows.
std::array<Vec3d, 3> labJacobian(const Vec3d& xyz, const Vec3d& white) {
    const double dx = labFDerivative(xyz.x / white.x) / white.x;
    const double dy = labFDerivative(xyz.y / white.y) / white.y;
    const double dz = labFDerivative(xyz.z / white.z) / white.z;
    return {Vec3d(0, 116 * dy, 0), Vec3d(500 * dx, -500 * dy, 0), Vec3d(0, 200 * dy, -200 * dz)};
}

}  // namespace

RgbToSpectrumFitter::RgbToSpectrumFitter() {
    const TabulatedCurve* d65 = findCieIlluminant("D65");
    double norm = 0;
    for (int i = 0; i < kSamples; ++i) {
        const double nm = kLambdaMin + double(i);
        const double w = (i == 0 || i == kSamples - 1) ? 0.5 : 1.0;  // trapezoid, 1 nm
        t_[std::size_t(i)] = (nm - kLambdaMin) / kWidth;
        const Vec3d cmf = cieXyz(nm) * ((*d65)(nm)*w);
        weights_[std::size_t(i)] = {cmf.x, cmf.y, cmf.z};
        norm += cmf.y;
    }
    // A reflectance of 1 has Y = 1: the white of the colour space.
    for (auto& w : weights_)
        for (double& v : w)
            v /= norm;
}

SigmoidPolynomial RgbToSpectrumFitter::toNanometres(const NormalizedCoefficients& c) {
    return SigmoidPolynomial::fromNormalized(c[0], c[1], c[2], kLambdaMin, kWidth);
}

Rgb<double> RgbToSpectrumFitter::colorOf(const NormalizedCoefficients& c) const {
    Vec3d xyz(0.0);
    for (int i = 0; i < kSamples; ++i) {
        const double t = t_[std::size_t(i)];
        const double s = SigmoidPolynomial::sigmoid((c[0] * t + c[1]) * t + c[2]);
        const auto& w = weights_[std::size_t(i)];
        xyz += s * Vec3d(w[0], w[1], w[2]);
    }
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
    return {rgb.x, rgb.y, rgb.z};
}

SigmoidFit RgbToSpectrumFitter::fit(const Rgb<double>& rgb, NormalizedCoefficients c) const {
    const RgbColorSpace& cs = RgbColorSpace::rec709();
    const Vec3d white = cs.whiteXyz();
    const Vec3d targetLab = toLab(cs.toXyz(Vec3d(rgb[0], rgb[1], rgb[2])), white);
    SigmoidFit result;
    for (int iteration = 0; iteration < 32; ++iteration) {
        // The colour of the current spectrum and its derivatives with respect to c:
        // dS/dx = 1 / (2 (1 + x^2)^(3/2)), dx/dc = (t^2, t, 1).
        Vec3d xyz(0.0);
        std::array<Vec3d, 3> dxyz{Vec3d(0.0), Vec3d(0.0), Vec3d(0.0)};  // per coefficient
        for (int i = 0; i < kSamples; ++i) {
            const double t = t_[std::size_t(i)];
            const double x = (c[0] * t + c[1]) * t + c[2];
            const double q = 1.0 + x * x;
            const double s = SigmoidPolynomial::sigmoid(x);
            const double ds = 0.5 / (q * std::sqrt(q));
            const auto& w = weights_[std::size_t(i)];
            const Vec3d wv(w[0], w[1], w[2]);
            xyz += s * wv;
            dxyz[0] += (ds * t * t) * wv;
            dxyz[1] += (ds * t) * wv;
            dxyz[2] += ds * wv;
        }
        const Vec3d residual = toLab(xyz, white) - targetLab;
        result.residual = glm::length(residual);
        result.coefficients = c;
        result.iterations = iteration;
        if (result.residual < 1e-6) break;
        const auto dLab = labJacobian(xyz, white);
        // J[r][k] = dLab_r / dc_k.
        Mat3<double> J;
        for (int k = 0; k < 3; ++k)
            for (int r = 0; r < 3; ++r)
                J[k][r] = glm::dot(dLab[std::size_t(r)], dxyz[std::size_t(k)]);  // column k
        if (std::abs(glm::determinant(J)) < 1e-300) break;
        const Vec3d step = glm::inverse(J) * residual;
        if (!std::isfinite(step.x) || !std::isfinite(step.y) || !std::isfinite(step.z)) break;
        for (int k = 0; k < 3; ++k)
            c[std::size_t(k)] -= step[k];
        // Far outside the useful range the spectrum is a step function already; stop before
        // the coefficients overflow (black and fully saturated corners of the cube).
        if (std::abs(c[0]) > 1e6 || std::abs(c[1]) > 1e6 || std::abs(c[2]) > 1e6) break;
    }
    return result;
}

}  // namespace lamina
