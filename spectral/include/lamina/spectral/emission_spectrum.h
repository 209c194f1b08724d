// Emission given as a spectrum (docs/spectral.md: a named spectrum is reduced to RGB in
// RGB mode): a CIE illuminant by name, a black body, or a list of (nm, value) pairs, times a
// scale. Named illuminants and black bodies are normalised to luminance Y = 1 first, so
// `scale` is their luminance; a list is taken as it is (W sr^-1 m^-2 nm^-1) times `scale`.
#pragma once

#include <functional>
#include <string>

#include "lamina/core/spectrum.h"

namespace lamina {

class EmissionSpectrum {
  public:
    /// "D65", "A", ... (CIE, from colord-data); throws InputError naming the known ones.
    static EmissionSpectrum illuminant(const std::string& name, double scale);
    static EmissionSpectrum blackbody(double kelvin, double scale);
    static EmissionSpectrum tabulated(std::vector<double> nm, std::vector<double> values,
                                      double scale, const std::string& what);

    double operator()(double nm) const { return scale_ * curve_(nm); }
    /// The RGB-mode value: the spectrum's colour (CIE 1931 XYZ -> linear Rec.709), with
    /// components below 0 (outside the gamut) clamped to 0.
    Rgb<double> rgb() const;
    const std::string& name() const { return name_; }

  private:
    EmissionSpectrum(std::string name, std::function<double(double)> curve, double scale);
    std::string name_;
    std::function<double(double)> curve_;
    double scale_;
};

}  // namespace lamina
