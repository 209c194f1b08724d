#include "lamina/spectral/emission_spectrum.h"

#include "lamina/core/error.h"
#include "lamina/spectral/blackbody.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/ior_spectrum.h"

namespace lamina {

namespace {

// Scales a curve so that its luminance Y = integral S y-bar / integral y-bar is 1.
std::function<double(double)> normalisedToLuminance(std::function<double(double)> f) {
    const Vec3d xyz = integrateAgainstCmf(f) / cieYIntegral();
    const double s = xyz.y > 0 ? 1.0 / xyz.y : 0.0;
    return [f = std::move(f), s](double nm) { return s * f(nm); };
}

}  // namespace

EmissionSpectrum::EmissionSpectrum(std::string name, std::function<double(double)> curve,
                                   double scale)
    : name_(std::move(name)), curve_(std::move(curve)), scale_(scale) {}

EmissionSpectrum EmissionSpectrum::illuminant(const std::string& name, double scale) {
    const TabulatedCurve* c = findCieIlluminant(name);
    if (!c) {
        std::string known;
        for (const auto& n : cieIlluminantNames())
            known += (known.empty() ? "" : ", ") + n;
        throw InputError("unknown CIE illuminant \"" + name + "\"; expected one of " + known);
    }
    return {"CIE " + name, normalisedToLuminance([c](double nm) { return (*c)(nm); }), scale};
}

EmissionSpectrum EmissionSpectrum::blackbody(double kelvin, double scale) {
    return {"blackbody " + std::to_string(int(kelvin)) + " K",
            normalisedToLuminance([kelvin](double nm) { return blackbodyRadiance(nm, kelvin); }),
            scale};
}

EmissionSpectrum EmissionSpectrum::tabulated(std::vector<double> nm, std::vector<double> values,
                                             double scale, const std::string& what) {
    return {what, tabulatedCurve(std::move(nm), std::move(values), what), scale};
}

Rgb<double> EmissionSpectrum::rgb() const {
    const Vec3d xyz =
        integrateAgainstCmf([this](double nm) { return (*this)(nm); }) / cieYIntegral();
    const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
    return {std::max(0.0, rgb.x), std::max(0.0, rgb.y), std::max(0.0, rgb.z)};
}

}  // namespace lamina
