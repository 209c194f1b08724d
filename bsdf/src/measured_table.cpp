#include "lamina/bsdf/measured_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "lamina/core/math.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina {

namespace {

// Far more than any measurement has (the RGL database's: some 200): each one costs a reduction
// to RGB over the whole visible range.
constexpr std::size_t kMaxWavelengths = 4096;

// The unit-square coordinates of the parameterisation (Dupuy and Jakob 2018, section 5: theta
// through a square root, which spreads the nodes towards the horizon, phi linearly).
double theta2u(double theta) {
    return std::sqrt(std::max(theta, 0.0) * (2.0 / kPi<double>));
}
double phi2u(double phi) {
    return (phi + kPi<double>)*(0.5 / kPi<double>);
}
double u2theta(double u) {
    return u * u * (0.5 * kPi<double>);
}
double u2phi(double u) {
    return (2.0 * u - 1.0) * kPi<double>;
}

// The polar angle of a unit vector, accurate near the pole (acos loses it there).
double elevation(const Vec3d& d) {
    const double dist = std::sqrt(d.x * d.x + d.y * d.y + (d.z - 1) * (d.z - 1));
    return 2.0 * std::asin(std::clamp(0.5 * dist, 0.0, 1.0));
}

[[noreturn]] void fail(const std::string& field, const std::string& what) {
    throw std::invalid_argument("field \"" + field + "\": " + what);
}

std::string shapeText(const std::vector<std::size_t>& shape) {
    std::string s = "[";
    for (std::size_t i = 0; i < shape.size(); ++i)
        s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + "]";
}

// `t` has `rank` axes; `expected` gives the size of some of them (0: any size >= minimum).
void checkShape(const std::string& field, const MeasuredTensor& t,
                const std::vector<std::size_t>& expected, std::size_t minimum = 1) {
    std::string want = "[";
    for (std::size_t i = 0; i < expected.size(); ++i)
        want += (i ? ", " : "") +
                (expected[i] ? std::to_string(expected[i]) : ">= " + std::to_string(minimum));
    want += "]";
    bool ok = t.shape.size() == expected.size();
    std::size_t count = 1;
    for (std::size_t i = 0; ok && i < expected.size(); ++i) {
        ok = expected[i] ? t.shape[i] == expected[i] : t.shape[i] >= minimum;
        count *= t.shape[i];
    }
    if (!ok) fail(field, "expected the shape " + want + ", got " + shapeText(t.shape));
    if (t.values.size() != count)
        fail(field, "holds " + std::to_string(t.values.size()) + " values for the shape " +
                        shapeText(t.shape));
    for (float v : t.values)
        if (!std::isfinite(v)) fail(field, "holds a value that is not a finite number");
}

void checkNonNegative(const std::string& field, const MeasuredTensor& t) {
    for (float v : t.values)
        if (v < 0) fail(field, "holds a negative value");
}

void checkIncreasing(const std::string& field, const std::vector<float>& grid) {
    for (std::size_t i = 1; i < grid.size(); ++i)
        if (!(grid[i] > grid[i - 1])) fail(field, "expected increasing values");
}

// The Rec.709 weights of each tabulated wavelength: a spectrum interpolated linearly between
// them (and held constant beyond the ends, as the spectral lookup does) reduces to RGB as the
// sum of its values times these, under D65 with the CIE 1931 observer (the reduction of
// reflectanceColor, without its clamp: these values are BRDFs, not reflectances).
std::vector<std::array<double, 3>> rgbWeights(const std::vector<float>& nm) {
    const std::size_t n = nm.size();
    std::vector<std::array<double, 3>> w(n);
    for (std::size_t k = 0; k < n; ++k) {
        auto hat = [&](double l) {
            if (n == 1) return 1.0;
            if (l <= nm[k]) {
                if (k == 0) return 1.0;
                return std::max(0.0, (l - nm[k - 1]) / (double(nm[k]) - nm[k - 1]));
            }
            if (k + 1 == n) return 1.0;
            return std::max(0.0, (double(nm[k + 1]) - l) / (double(nm[k + 1]) - nm[k]));
        };
        const Vec3d xyz = integrateAgainstCmf([&](double l) { return hat(l) * d65Normalized(l); }) /
                          cieYIntegral();
        const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
        w[k] = {rgb.x, rgb.y, rgb.z};
    }
    return w;
}

}  // namespace

MeasuredBsdfTable::MeasuredBsdfTable(MeasuredBsdfFields f) : description_(f.description) {
    checkShape("theta_i", f.thetaI, {0});
    checkShape("phi_i", f.phiI, {0});
    checkIncreasing("theta_i", f.thetaI.values);
    checkIncreasing("phi_i", f.phiI.values);
    const std::size_t nPhi = f.phiI.shape[0], nTheta = f.thetaI.shape[0];
    checkShape("ndf", f.ndf, {0, 0}, 2);
    checkShape("sigma", f.sigma, {0, 0}, 2);
    checkNonNegative("ndf", f.ndf);
    checkNonNegative("sigma", f.sigma);
    checkShape("vndf", f.vndf, {nPhi, nTheta, 0, 0}, 2);
    checkShape("luminance", f.luminance, {nPhi, nTheta, 0, 0}, 2);
    const std::size_t rows = f.luminance.shape[2], cols = f.luminance.shape[3];
    if (f.spectra.has_value() == f.rgb.has_value())
        throw std::invalid_argument("expected either the field \"spectra\" or \"rgb\"");
    std::vector<float> channels{0.0f, 1.0f, 2.0f};
    MeasuredTensor* values = nullptr;
    if (f.spectra) {
        if (!f.wavelengths) throw std::invalid_argument("the field \"wavelengths\" is missing");
        checkShape("wavelengths", *f.wavelengths, {0});
        if (f.wavelengths->shape[0] > kMaxWavelengths)
            fail("wavelengths", "expected at most " + std::to_string(kMaxWavelengths) + " values");
        checkIncreasing("wavelengths", f.wavelengths->values);
        checkShape("spectra", *f.spectra, {nPhi, nTheta, f.wavelengths->shape[0], rows, cols});
        wavelengths_ = f.wavelengths->values;
        values = &*f.spectra;
    } else {
        checkShape("rgb", *f.rgb, {nPhi, nTheta, 3, rows, cols});
        values = &*f.rgb;
    }
    valueShape_ = values->shape;
    // At most two phi_i: isotropic (Mitsuba 3's test). Otherwise the range of phi_i says which
    // symmetry the data were reduced by: the whole turn, a half or a quarter.
    isotropic_ = nPhi <= 2;
    if (!isotropic_) {
        const double span = double(f.phiI.values.back()) - double(f.phiI.values.front());
        reduction_ = int(std::rint(2.0 * kPi<double> / span));
        if (reduction_ != 1 && reduction_ != 2 && reduction_ != 4)
            fail("phi_i", "expected a range of a whole, a half or a quarter turn");
    }
    jacobian_ = f.jacobian;

    using Kind = MarginalWarp2D::Kind;
    const std::vector<std::vector<float>> angles{f.phiI.values, f.thetaI.values};
    ndf_ = MarginalWarp2D(int(f.ndf.shape[1]), int(f.ndf.shape[0]), {}, std::move(f.ndf.values),
                          Kind::Values);
    sigma_ = MarginalWarp2D(int(f.sigma.shape[1]), int(f.sigma.shape[0]), {},
                            std::move(f.sigma.values), Kind::Values);
    vndf_ = MarginalWarp2D(int(f.vndf.shape[3]), int(f.vndf.shape[2]), angles,
                           std::move(f.vndf.values), Kind::Density);
    luminance_ =
        MarginalWarp2D(int(cols), int(rows), angles, std::move(f.luminance.values), Kind::Density);
    const std::size_t perSlice = rows * cols, nChannels = valueShape_[2];
    if (spectral()) {
        // The spectra reduced to RGB once, so that RGB mode reads three tables, not one per
        // wavelength.
        const auto w = rgbWeights(wavelengths_);
        std::vector<float> rgb(nPhi * nTheta * 3 * perSlice);
        for (std::size_t a = 0; a < nPhi * nTheta; ++a)
            for (std::size_t c = 0; c < 3; ++c)
                for (std::size_t i = 0; i < perSlice; ++i) {
                    double sum = 0;
                    for (std::size_t k = 0; k < nChannels; ++k)
                        sum += w[k][c] * double(values->values[(a * nChannels + k) * perSlice + i]);
                    rgb[(a * 3 + c) * perSlice + i] = float(sum);
                }
        rgb_ = MarginalWarp2D(int(cols), int(rows), {f.phiI.values, f.thetaI.values, channels},
                              std::move(rgb), Kind::Values);
    }
    values_ = MarginalWarp2D(int(cols), int(rows),
                             {f.phiI.values, f.thetaI.values, spectral() ? wavelengths_ : channels},
                             std::move(values->values), Kind::Values);
}

namespace {

// The signs that fold wo into the part of the circle a reduced file covers (Mitsuba 3's
// `measured`: a half turn when phi_i cover half the circle, a mirror in x and in y when they
// cover a quarter), applied to a direction; applied twice, they give it back.
struct Fold {
    double sx = 1, sy = 1;
    Fold(const Vec3d& wo, int reduction) {
        if (reduction < 2) return;
        sy = wo.y >= 0 ? -1 : 1;
        sx = reduction == 4 ? (wo.x >= 0 ? -1 : 1) : sy;
    }
    Vec3d operator()(const Vec3d& w) const { return {w.x * sx, w.y * sy, w.z}; }
};

}  // namespace

std::optional<MeasuredBsdfTable::Lookup> MeasuredBsdfTable::lookup(const Vec3d& woIn,
                                                                   const Vec3d& wiIn) const {
    if (!(woIn.z * wiIn.z > 0)) return std::nullopt;
    const double side = woIn.z > 0 ? 1.0 : -1.0;
    const Fold fold(side * woIn, reduction_);
    const Vec3d wo = fold(side * woIn), wi = fold(side * wiIn);
    const Vec3d sum = wo + wi;
    const double length = glm::length(sum);
    if (!(length > 0)) return std::nullopt;
    const Vec3d wm = sum / length;
    const double thetaO = elevation(wo), phiO = std::atan2(wo.y, wo.x);
    const double thetaM = elevation(wm), phiM = std::atan2(wm.y, wm.x);
    const Vec2d uWo(theta2u(thetaO), phi2u(phiO));
    Vec2d uM(theta2u(thetaM), phi2u(isotropic_ ? phiM - phiO : phiM));
    uM.y -= std::floor(uM.y);
    Lookup l;
    l.params[0] = phiO;
    l.params[1] = thetaO;
    const auto [ui, vndfPdf] = vndf_.invert(uM, l.params);
    l.ui = ui;
    l.scale = 1;
    if (jacobian_) {
        const double sigma = sigma_.eval(uWo, {});
        l.scale = sigma > 0 ? ndf_.eval(uM, {}) / (4 * sigma) : 0.0;
    }
    // The density of u(wm) turned into one of wi: d(u) / d(omega_m) = 1 / (2 pi^2 u_x
    // sin theta_m), and the reflection's 1 / (4 wo.wm) (Walter et al. 2007, eq. 14).
    const double sinThetaM = std::sqrt(std::max(0.0, 1 - wm.z * wm.z));
    const double jacobian =
        std::max(2 * kPi<double> * kPi<double> * uM.x * sinThetaM, 1e-6) * 4 * glm::dot(wo, wm);
    l.pdf = jacobian > 0 ? vndfPdf * luminance_.eval(ui, l.params) / jacobian : 0.0;
    // Finite tables can still overflow (a huge D over a tiny sigma): no Inf leaves here.
    if (!std::isfinite(l.scale) || !std::isfinite(l.pdf)) return std::nullopt;
    return l;
}

double MeasuredBsdfTable::value(const Lookup& l, double channel) const {
    const double p[3] = {l.params[0], l.params[1], channel};
    const double v = std::max(0.0, values_.eval(l.ui, p)) * l.scale;
    return std::isfinite(v) ? v : 0.0;
}

double MeasuredBsdfTable::rgbValue(const Lookup& l, int c) const {
    const double p[3] = {l.params[0], l.params[1], double(c)};
    const double v = std::max(0.0, (spectral() ? rgb_ : values_).eval(l.ui, p)) * l.scale;
    return std::isfinite(v) ? v : 0.0;
}

std::optional<Vec3d> MeasuredBsdfTable::sample(const Vec3d& woIn, const Vec2d& u) const {
    if (woIn.z == 0) return std::nullopt;
    const double side = woIn.z > 0 ? 1.0 : -1.0;
    const Fold fold(side * woIn, reduction_);
    const Vec3d wo = fold(side * woIn);
    const double thetaO = elevation(wo), phiO = std::atan2(wo.y, wo.x);
    const double params[2] = {phiO, thetaO};
    const Vec2d ui = luminance_.sample(u, params).first;
    const Vec2d uM = vndf_.sample(ui, params).first;
    const double thetaM = u2theta(uM.x), phiM = u2phi(uM.y) + (isotropic_ ? phiO : 0.0);
    const Vec3d wm(std::sin(thetaM) * std::cos(phiM), std::sin(thetaM) * std::sin(phiM),
                   std::cos(thetaM));
    const Vec3d wi = reflect(wo, wm);
    if (!(wi.z > 0)) return std::nullopt;
    return side * fold(wi);
}

}  // namespace lamina
