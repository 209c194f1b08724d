#include "lamina/experiments/polarisation_materials.h"

#include <cmath>
#include <filesystem>
#include <functional>

#include "lamina/core/error.h"
#include "lamina/experiments/material_names.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

MuellerMatrix<double> specularReflectionMueller(std::complex<double> index, double degrees) {
    // cos(90 degrees) is 6e-17 in floating point: grazing incidence is exactly 0.
    const double cosTheta = degrees >= 90 ? 0.0 : std::cos(radians(degrees));
    return fresnelReflectionMueller(fresnelAmplitudes(cosTheta, index));
}

namespace {

/// The phase of r_s conj(r_p) = M22 + i M23 in degrees, in [-90, 270) (the header says why).
double retardanceDegrees(const MuellerMatrix<double>& m) {
    double delta = degrees(std::atan2(m(2, 3), m(2, 2)));
    if (delta < -90) delta += 360;
    return delta + 0.0;  // no -0
}

/// Bisection of f's sign change in [lo, hi] (f(lo) and f(hi) of opposite signs or one 0) to
/// the resolution of double.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
    const bool negativeAtLo = f(lo) < 0;
    for (int i = 0; i < 200 && lo < hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (f(mid) < 0) == negativeAtLo ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi);
}

/// The minimum of a unimodal f in [lo, hi] by golden-section search.
double goldenMinimum(const std::function<double(double)>& f, double lo, double hi) {
    const double g = (std::sqrt(5.0) - 1) / 2;
    double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    double fa = f(a), fb = f(b);
    for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
        if (fa < fb) {
            hi = b;
            b = a;
            fb = fa;
            a = hi - g * (hi - lo);
            fa = f(a);
        } else {
            lo = a;
            a = b;
            fa = fb;
            b = lo + g * (hi - lo);
            fb = f(b);
        }
    }
    return 0.5 * (lo + hi);
}

MuellerCurve curveAt(const IorSpectrum& ior, double nm, const std::vector<double>& degrees) {
    MuellerCurve c;
    c.nm = nm;
    c.index = {ior.n(nm), ior.k(nm)};
    for (const double d : degrees) {
        const MuellerMatrix<double> m = specularReflectionMueller(c.index, d);
        c.mueller.push_back(m);
        c.rs.push_back(m(0, 0) + m(0, 1));
        c.rp.push_back(m(0, 0) - m(0, 1));
        c.diattenuation.push_back(m(0, 0) > 0 ? m(0, 1) / m(0, 0) : 0.0);
        c.retardance.push_back(retardanceDegrees(m));
    }
    const auto m22 = [&](double d) { return specularReflectionMueller(c.index, d)(2, 2); };
    const auto rp = [&](double d) {
        const MuellerMatrix<double> m = specularReflectionMueller(c.index, d);
        return m(0, 0) - m(0, 1);
    };
    // The first sign change of the tabulated M22 (it is -Rs at normal incidence, +1 at grazing),
    // refined between its two angles; M22 exactly 0 on the table is the angle itself.
    for (std::size_t a = 0; a + 1 < degrees.size() && !c.principalAngle; ++a) {
        const double here = c.mueller[a](2, 2), next = c.mueller[a + 1](2, 2);
        if (here == 0)
            c.principalAngle = degrees[a];
        else if ((here < 0) != (next < 0) && next != 0)
            c.principalAngle = bisect(m22, degrees[a], degrees[a + 1]);
    }
    // The tabulated minimum of Rp, refined between its neighbours.
    std::size_t least = 0;
    for (std::size_t a = 1; a < degrees.size(); ++a)
        if (c.rp[a] < c.rp[least]) least = a;
    const double lo = degrees[least == 0 ? 0 : least - 1];
    const double hi = degrees[std::min(least + 1, degrees.size() - 1)];
    c.minimumRpAngle = goldenMinimum(rp, lo, hi);
    c.minimumRp = rp(c.minimumRpAngle);
    return c;
}

}  // namespace

PolarisationMaterialsResult runPolarisationMaterials(const PolarisationMaterialsInputs& in) {
    PolarisationMaterialsResult r;
    const int steps = int(std::lround(90 / kMuellerAngleStep));
    for (int a = 0; a <= steps; ++a)
        r.degrees.push_back(a * kMuellerAngleStep);
    for (const double nm : in.wavelengths)
        if (!(nm >= 360 && nm <= 830))
            throw InputError(
                formatText("--wavelengths: %g nm: expected 360 to 830 nm, the range "
                           "lamina renders",
                           nm));
    for (const std::string& name : in.materials) {
        const IorSpectrum ior = loadNamedMaterial(name);
        PolarisationMaterial m;
        m.stem = std::filesystem::path(name).stem().string();
        m.name = ior.name();
        m.conductor = isConductor(ior);
        for (const double nm : in.wavelengths)
            m.curves.push_back(curveAt(ior, nm, r.degrees));
        r.materials.push_back(std::move(m));
    }
    return r;
}

}  // namespace lamina::experiments
