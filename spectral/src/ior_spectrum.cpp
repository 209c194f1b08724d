#include "lamina/spectral/ior_spectrum.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "dispersion_formulas.h"
#include "lamina/core/error.h"
#include "lamina/core/fresnel_equations.h"
#include "lamina/core/input_file.h"
#include "lamina/core/math.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "measured_metals.h"

namespace lamina {

// refractiveindex.info dispersion formulas (lambda in um):
//   1: n^2 - 1 = C1 + sum_i C(2i) l^2 / (l^2 - C(2i+1)^2)   (Sellmeier)
//   2: n^2 - 1 = C1 + sum_i C(2i) l^2 / (l^2 - C(2i+1))     (Sellmeier-2)
double dispersionFormula(int formula, const std::vector<double>& c, double nm) {
    const double l2 = (nm * 1e-3) * (nm * 1e-3);
    double n2 = 1.0 + c[0];
    for (std::size_t i = 1; i + 1 < c.size(); i += 2) {
        const double b = formula == 1 ? c[i + 1] * c[i + 1] : c[i + 1];
        n2 += c[i] * l2 / (l2 - b);
    }
    return std::sqrt(std::max(n2, 0.0));
}

IorSpectrum::Curve formulaCurve(int formula, std::vector<double> c) {
    return [formula, c = std::move(c)](double nm) { return dispersionFormula(formula, c, nm); };
}

double noAbsorption(double) {
    return 0.0;
}

IorSpectrum::IorSpectrum(std::string name, Curve n, Curve k, bool dispersive)
    : name_(std::move(name)), n_(std::move(n)), k_(std::move(k)), dispersive_(dispersive) {}

IorSpectrum IorSpectrum::constant(double n, double k) {
    return IorSpectrum(
        "constant", [n](double) { return n; }, [k](double) { return k; }, false);
}

IorSpectrum::Curve tabulatedCurve(std::vector<double> nm, std::vector<double> values,
                                  std::string what) {
    auto warned = std::make_shared<std::atomic<bool>>(false);
    return
        [nm = std::move(nm), values = std::move(values), what = std::move(what), warned](double x) {
            if (x < nm.front() || x > nm.back()) {
                if (!warned->exchange(true))
                    std::cerr << "lamina: warning: " << what << ": data cover " << nm.front() << "-"
                              << nm.back() << " nm; " << x
                              << " nm and other wavelengths outside use the end values\n";
                return x < nm.front() ? values.front() : values.back();
            }
            const auto it = std::upper_bound(nm.begin(), nm.end(), x);
            const std::size_t i = std::min(std::size_t(it - nm.begin()), nm.size() - 1);
            if (i == 0) return values.front();
            const double t = (x - nm[i - 1]) / (nm[i] - nm[i - 1]);
            return (1 - t) * values[i - 1] + t * values[i];
        };
}

namespace {

// Rakic, Djurisic, Elazar and Majewski 1998, "Optical properties of metallic films for
// vertical-cavity optoelectronic devices", Appl. Opt. 37(22), 5271-5283, Tables 1 and 2 (LD
// model): plasma energy wp, then (f, w, Gamma) per oscillator in eV, the first with w = 0
// (the Drude term). Values as listed in ../shared/data/LD.md.
struct LdMetal {
    const char* name;
    double wp;
    std::array<std::array<double, 3>, 6> terms;  // (f, w, Gamma); unused terms have f = 0
};

constexpr LdMetal kLdMetals[] = {
    {"Ag",
     9.01,
     {{{0.845, 0, 0.048},
       {0.065, 0.816, 3.886},
       {0.124, 4.481, 0.452},
       {0.011, 8.185, 0.065},
       {0.84, 9.083, 0.916},
       {5.646, 20.29, 2.419}}}},
    {"Au",
     9.03,
     {{{0.76, 0, 0.053},
       {0.024, 0.415, 0.241},
       {0.01, 0.83, 0.345},
       {0.071, 2.969, 0.87},
       {0.601, 4.304, 2.494},
       {4.384, 13.32, 2.214}}}},
    {"Cu",
     10.83,
     {{{0.575, 0, 0.03},
       {0.061, 0.291, 0.378},
       {0.104, 2.957, 1.056},
       {0.723, 5.3, 3.213},
       {0.638, 11.18, 4.305},
       {0, 0, 0}}}},
    {"Al",
     14.98,
     {{{0.523, 0, 0.047},
       {0.227, 0.162, 0.333},
       {0.05, 1.544, 0.312},
       {0.166, 1.808, 1.351},
       {0.03, 3.473, 3.382},
       {0, 0, 0}}}},
    {"Be",
     18.51,
     {{{0.084, 0, 0.035},
       {0.031, 0.1, 1.664},
       {0.14, 1.032, 3.395},
       {0.53, 3.183, 4.454},
       {0.13, 4.604, 1.802},
       {0, 0, 0}}}},
    {"Cr",
     10.75,
     {{{0.168, 0, 0.047},
       {0.151, 0.121, 3.175},
       {0.15, 0.543, 1.305},
       {1.149, 1.97, 2.676},
       {0.825, 8.775, 1.335},
       {0, 0, 0}}}},
    {"Ni",
     15.92,
     {{{0.096, 0, 0.048},
       {0.1, 0.174, 4.511},
       {0.135, 0.582, 1.334},
       {0.106, 1.597, 2.178},
       {0.729, 6.089, 6.292},
       {0, 0, 0}}}},
    {"Pd",
     9.72,
     {{{0.33, 0, 0.008},
       {0.649, 0.336, 2.95},
       {0.121, 0.501, 0.555},
       {0.638, 1.659, 4.621},
       {0.453, 5.715, 3.236},
       {0, 0, 0}}}},
    {"Pt",
     9.59,
     {{{0.333, 0, 0.08},
       {0.191, 0.78, 0.517},
       {0.659, 1.314, 1.838},
       {0.547, 3.141, 3.668},
       {3.576, 9.249, 8.517},
       {0, 0, 0}}}},
    {"Ti",
     7.29,
     {{{0.148, 0, 0.082},
       {0.899, 0.777, 2.276},
       {0.393, 1.545, 2.518},
       {0.187, 2.509, 1.663},
       {0.001, 19.43, 1.762},
       {0, 0, 0}}}},
    {"W",
     13.22,
     {{{0.206, 0, 0.064},
       {0.054, 1.004, 0.53},
       {0.166, 1.917, 1.281},
       {0.706, 3.58, 3.332},
       {2.59, 7.498, 5.836},
       {0, 0, 0}}}},
};

const LdMetal* findLdMetal(const std::string& name) {
    for (const auto& m : kLdMetals)
        if (name == m.name) return &m;
    return nullptr;
}

struct NamedGlass {
    const char* name;
    int formula;
    std::vector<double> coefficients;
};

// Coefficients as published (via the refractiveindex.info database, ../shared/data/nk):
const NamedGlass kGlasses[] = {
    // SCHOTT N-BK7, Zemax catalogue 2017-01-20b (formula 2).
    {"bk7", 2, {0, 1.03961212, 0.00600069867, 0.231792344, 0.0200179144, 1.01046945, 103.560653}},
    // Fused silica, Malitson 1965, J. Opt. Soc. Am. 55, 1205 (formula 1).
    {"fused_silica", 1, {0, 0.6961663, 0.0684043, 0.4079426, 0.1162414, 0.8974794, 9.896161}},
    // Water at 20 C, Daimon and Masumura 2007, Appl. Opt. 46, 3811 (formula 2).
    {"water",
     2,
     {0, 5.684027565E-1, 5.101829712E-3, 1.726177391E-1, 1.821153936E-2, 2.086189578E-2,
      2.620722293E-2, 1.130748688E-1, 1.069792721E1}},
    // Diamond, Peter 1923, Z. Phys. 15, 358 (formula 1).
    {"diamond", 1, {0, 0.3306, 0.1750, 4.3356, 0.1060}},
};

}  // namespace

std::complex<double> lorentzDrudeIndex(const std::string& metal, double nm) {
    const LdMetal* m = findLdMetal(metal);
    if (!m) throw InputError("unknown Lorentz-Drude metal \"" + metal + "\"");
    const double w = 1.23984193 / (nm * 1e-3);  // photon energy in eV
    const double wp2 = m->wp * m->wp;
    using C = std::complex<double>;
    const auto& d = m->terms[0];
    C eps = 1.0 - d[0] * wp2 / (w * C(w, d[2]));
    for (std::size_t j = 1; j < m->terms.size(); ++j) {
        const auto& t = m->terms[j];
        if (t[0] == 0) continue;
        eps += t[0] * wp2 / C(t[1] * t[1] - w * w, -w * t[2]);
    }
    return std::sqrt(eps);  // principal branch: k >= 0
}

IorSpectrum cauchyIor(double a, double b, double c) {
    return IorSpectrum(
        "Cauchy",
        [a, b, c](double nm) {
            const double l2 = sqr(nm * 1e-3);
            return a + b / l2 + c / (l2 * l2);
        },
        noAbsorption, b != 0 || c != 0);
}

IorSpectrum sellmeierIor(const std::vector<double>& b, const std::vector<double>& c) {
    std::vector<double> coefficients{0.0};  // formula 2: no constant term
    for (std::size_t i = 0; i < b.size(); ++i) {
        coefficients.push_back(b[i]);
        coefficients.push_back(c[i]);
    }
    return IorSpectrum("Sellmeier", formulaCurve(2, std::move(coefficients)), noAbsorption, true);
}

namespace {

// "JohnsonChristy1972" -> "Johnson and Christy 1972", "Rakic1995" -> "Rakic 1995".
std::string citation(const std::string& source) {
    std::string out;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const char c = source[i];
        if (i > 0 && std::isupper(static_cast<unsigned char>(c))) out += " and ";
        if (i > 0 && std::isdigit(static_cast<unsigned char>(c)) &&
            !std::isdigit(static_cast<unsigned char>(source[i - 1])))
            out += ' ';
        out += c;
    }
    return out;
}

IorSpectrum lorentzDrudeSpectrum(const std::string& metal) {
    return IorSpectrum(
        metal + " (Rakic 1998 Lorentz-Drude)",
        [metal](double nm) { return lorentzDrudeIndex(metal, nm).real(); },
        [metal](double nm) { return lorentzDrudeIndex(metal, nm).imag(); }, true);
}

}  // namespace

std::optional<IorSpectrum> namedIor(const std::string& name) {
    for (const MeasuredMetal& m : measuredMetals()) {
        if (name != m.metal) continue;
        std::vector<double> nm, n, k;
        for (const MeasuredNk& s : m.samples) {
            nm.push_back(s.nm);
            n.push_back(s.n);
            k.push_back(s.k);
        }
        const std::string what = name + " (" + citation(m.source) + ")";
        return IorSpectrum(what, tabulatedCurve(nm, n, what),
                           tabulatedCurve(nm, std::move(k), what), true);
    }
    // The fits: under their own names ("Cu_LD"), and under the plain name for the metals
    // without measured data (Be, Pd).
    const std::string ldSuffix = "_LD";
    if (name.size() > ldSuffix.size() && name.ends_with(ldSuffix)) {
        const std::string metal = name.substr(0, name.size() - ldSuffix.size());
        if (findLdMetal(metal)) return lorentzDrudeSpectrum(metal);
    } else if (findLdMetal(name)) {
        return lorentzDrudeSpectrum(name);
    }
    for (const auto& g : kGlasses)
        if (name == g.name)
            return IorSpectrum(g.name, formulaCurve(g.formula, g.coefficients), noAbsorption, true);
    return std::nullopt;
}

std::vector<std::string> namedMetalNames() {
    std::vector<std::string> names;
    for (const MeasuredMetal& m : measuredMetals())
        names.emplace_back(m.metal);
    for (const auto& m : kLdMetals)
        if (std::find(names.begin(), names.end(), m.name) == names.end())
            names.emplace_back(m.name);
    for (const auto& m : kLdMetals)
        names.emplace_back(std::string(m.name) + "_LD");
    return names;
}

std::vector<std::string> namedGlassNames() {
    std::vector<std::string> names;
    for (const auto& g : kGlasses)
        names.emplace_back(g.name);
    return names;
}

std::pair<Rgb<double>, Rgb<double>> conductorF0F82(const IorSpectrum& ior) {
    auto colour = [&](double cosTheta) {
        const Vec3d xyz =
            integrateAgainstCmf([&](double nm) {
                return fresnelConductor(cosTheta, ior.n(nm), ior.k(nm)) * d65Normalized(nm);
            }) /
            cieYIntegral();
        const Vec3d rgb = RgbColorSpace::rec709().toRgb(xyz);
        return Rgb<double>(rgb.x, rgb.y, rgb.z);
    };
    return {colour(1.0), colour(1.0 / 7.0)};
}

}  // namespace lamina
