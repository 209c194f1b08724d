// RGB -> spectrum (Jakob and Hanika 2019): a linear Rec.709 colour becomes a smooth
// sigmoid-polynomial spectrum, by trilinear interpolation in the coefficient table lamina's
// own optimiser computes at build time (rgb_to_spectrum_fit.h). Three flavours:
//   reflectance  rgb in [0, 1]^3 (clamped) -> s(lambda) in [0, 1]; its colour under D65 is rgb.
//   unbounded    any rgb >= 0: m = max component, s = 2m * reflectance(rgb / 2m), so the
//                scaled colour sits in the middle of the table (pbrt-v4's convention).
//   illuminant   unbounded(rgb) * D65(lambda) / (Y of D65): RGB (1, 1, 1) is exactly the D65
//                white and stays white (pbrt-v4 issues 54 and 82).
#pragma once

#include <functional>
#include <span>

#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"
#include "lamina/spectral/sigmoid_polynomial.h"

namespace lamina {

class RgbToSpectrumTable {
  public:
    /// The table compiled into lamina_spectral.
    static const RgbToSpectrumTable& rec709();

    RgbToSpectrumTable(int resolution, std::span<const float> scale, std::span<const float> data)
        : res_(resolution), scale_(scale), data_(data) {}

    /// The coefficients for an RGB reflectance (components clamped to [0, 1]).
    SigmoidPolynomial lookup(Rgb<double> rgb) const;
    int resolution() const { return res_; }

  private:
    int res_;
    std::span<const float> scale_, data_;
};

enum class RgbSpectrumKind { Reflectance, Unbounded, Illuminant };
inline constexpr NameTable kRgbSpectrumKindNames{
    std::array{NameEntry{RgbSpectrumKind::Reflectance, "reflectance"},
               NameEntry{RgbSpectrumKind::Unbounded, "unbounded"},
               NameEntry{RgbSpectrumKind::Illuminant, "illuminant"}}};

/// A spectrum upsampled from RGB, evaluated at any wavelength.
class RgbSpectrum {
  public:
    RgbSpectrum(const Rgb<double>& rgb, RgbSpectrumKind kind);
    double operator()(double nm) const;
    /// True when operator() gives the same value at every wavelength (a grey reflectance or
    /// unbounded value: the sigmoid of a constant polynomial): value() is then that value.
    bool isConstant() const { return !illuminant_ && poly_.c0 == 0.0 && poly_.c1 == 0.0; }
    double value() const { return scale_ * SigmoidPolynomial::sigmoid(poly_.c2); }

  private:
    SigmoidPolynomial poly_;
    double scale_ = 1;
    bool illuminant_ = false;
};

/// The linear Rec.709 colour of a reflectance spectrum under D65 (components clamped to
/// [0, 1]): what RGB mode uses for a measured reflectance.
Rgb<double> reflectanceColor(const std::function<double(double)>& reflectance);

/// D65 relative spectral power normalised so that its luminance Y is 1 (CIE convention
/// Y = integral of S y-bar / integral of y-bar).
double d65Normalized(double nm);

}  // namespace lamina
