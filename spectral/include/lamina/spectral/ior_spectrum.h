// Complex index of refraction as a function of wavelength: n(lambda) + i k(lambda), from
// constants, measured tables (linear interpolation in wavelength; outside the data's range
// the end values are used and a warning is printed once), dispersion formulas, or the
// Lorentz-Drude model of Rakic et al. 1998. Named presets cover measured metals, the metals of
// that paper and common glasses; refractiveindex.info YAML files and plain CSV files load from disk.
#pragma once

#include <atomic>
#include <complex>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/spectrum.h"

namespace lamina {

class IorSpectrum {
  public:
    using Curve = std::function<double(double nm)>;

    /// n (and k) independent of wavelength.
    static IorSpectrum constant(double n, double k = 0.0);
    /// A curve per part; `dispersive` says whether n varies with wavelength.
    IorSpectrum(std::string name, Curve n, Curve k, bool dispersive);

    double n(double nm) const { return n_(nm); }
    double k(double nm) const { return k_(nm); }
    const std::string& name() const { return name_; }
    /// True when the real index varies with wavelength (refraction splits colours).
    bool dispersive() const { return dispersive_; }

  private:
    std::string name_;
    Curve n_, k_;
    bool dispersive_ = false;
};

/// Samples (nm, value) interpolated linearly; outside the range the end value, with a
/// one-time warning naming `what`. Wavelengths must increase strictly.
IorSpectrum::Curve tabulatedCurve(std::vector<double> nm, std::vector<double> values,
                                  std::string what);

/// Dispersion formulas of a dielectric (k = 0), the wavelength l in um:
///   Cauchy     n = A + B / l^2 + C / l^4 (dispersive unless B = C = 0), named "Cauchy";
///   Sellmeier  n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i), C_i in um^2, b and c of one length
///              (refractiveindex.info's formula 2 without its constant term), named
///              "Sellmeier".
IorSpectrum cauchyIor(double a, double b, double c);
IorSpectrum sellmeierIor(const std::vector<double>& b, const std::vector<double>& c);

/// A named metal or glass; nullopt for an unknown name. Metals by symbol are measured data
/// (spectral/data/nk: Johnson and Christy 1972 for Ag, Au, Cu and 1974 for Cr, Fe, Ni, Ti;
/// Rakic 1995 for Al; Tselin et al. 2024 for Pt; Weaver et al. 1975 for W; Werner et al. 2009
/// for Zn), linearly interpolated; the Lorentz-Drude fits of Rakic et al. 1998 are "SYMBOL_LD"
/// (Ag, Au, Cu, Al, Be, Cr, Ni, Pd, Pt, Ti, W) and, for Be and Pd, which have no measured
/// table here, also the plain symbol. Glasses: bk7, fused_silica, water, diamond.
std::optional<IorSpectrum> namedIor(const std::string& name);
std::vector<std::string> namedMetalNames();
std::vector<std::string> namedGlassNames();

/// The Lorentz-Drude index of one of Rakic's metals at a wavelength in nm.
std::complex<double> lorentzDrudeIndex(const std::string& metal, double nm);

/// Loads a refractiveindex.info database file (YAML: "tabulated nk", "tabulated n",
/// "tabulated k", "formula 1", "formula 2") or a CSV file (nm, n, k per line; '#' comments,
/// an optional header line). Errors name the file and what was wrong.
IorSpectrum loadIorFile(const std::filesystem::path& path);

/// RGB-mode reductions (Hoffman 2019, "Fresnel Equations Considered Harmful"): a conductor's
/// normal-incidence reflectance F0 and its reflectance at cos = 1/7 (F82), each the colour
/// (linear Rec.709) of the exact spectral Fresnel reflectance under D65.
std::pair<Rgb<double>, Rgb<double>> conductorF0F82(const IorSpectrum& ior);

/// The RGB-mode index of a dispersive dielectric: n at the helium d-line, 587.56 nm.
inline constexpr double kDLineNm = 587.56;

}  // namespace lamina
