// Spectra and colour as NumPy arrays over given wavelengths (nm): the n, k of a named metal
// or an n/k file, a glass's n(lambda), CIE illuminants and black bodies as scenes mean them,
// the CIE 1931 colour matching functions, XYZ <-> linear Rec.709, RGB -> spectrum (Jakob and
// Hanika 2019, lamina's table) and the RGB-mode reductions of a conductor (F0, F82).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lamina/core/error.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::python {

namespace {

/// `f` at every wavelength of `nm` (any shape), as an array of the same shape.
template <typename F>
py::array_t<double> overWavelengths(const DoubleArray& nm, F&& f) {
    std::vector<py::ssize_t> shape(nm.shape(), nm.shape() + nm.ndim());
    py::array_t<double> out(shape);
    const double* in = nm.data();
    double* o = out.mutable_data();
    for (py::ssize_t i = 0; i < nm.size(); ++i) {
        if (!std::isfinite(in[i]) || !(in[i] > 0))
            throw py::value_error("wavelengths: expected positive wavelengths in nm");
        o[i] = f(in[i]);
    }
    return out;
}

/// A named metal or glass, or an n/k file (YAML or CSV), as `lamina spectrum` resolves it.
IorSpectrum iorOf(const std::string& name) {
    if (auto ior = namedIor(name)) return *ior;
    if (name.find('.') != std::string::npos || name.find('/') != std::string::npos)
        return loadIorFile(name);
    std::string known;
    for (const auto& n : namedMetalNames())
        known += (known.empty() ? "" : ", ") + n;
    for (const auto& n : namedGlassNames())
        known += ", " + n;
    throw InputError(name + ": not a named metal or glass (" + known + ") nor an n/k file");
}

py::array_t<double> vec3Rows(const DoubleArray& in, const char* what, const Mat3<double>& matrix) {
    const Rows r = rowsOf(in, 3, what);
    py::array_t<double> out(r.shared ? std::vector<py::ssize_t>{3}
                                     : std::vector<py::ssize_t>{py::ssize_t(r.count), 3});
    double* o = out.mutable_data();
    for (std::size_t i = 0; i < (r.shared ? 1 : r.count); ++i) {
        const double* p = r.row(i);
        const Vec3d v = matrix * Vec3d(p[0], p[1], p[2]);
        for (int c = 0; c < 3; ++c)
            o[i * 3 + std::size_t(c)] = v[c];
    }
    return out;
}

py::array_t<double> rgbArray(const Rgb<double>& c) {
    py::array_t<double> out(3);
    for (int i = 0; i < 3; ++i)
        out.mutable_data()[i] = c[i];
    return out;
}

}  // namespace

void bindSpectra(py::module_& m) {
    m.def("metals", &namedMetalNames, "The named metals (Lorentz-Drude, Rakic et al. 1998)");
    m.def("glasses", &namedGlassNames, "The named glasses");
    m.def("illuminants", &cieIlluminantNames, "The CIE illuminants (colord-data)");

    m.def(
        "ior",
        [](const std::string& name, const DoubleArray& nm) {
            const IorSpectrum ior = iorOf(name);
            py::dict d;
            d["n"] = overWavelengths(nm, [&](double l) { return ior.n(l); });
            d["k"] = overWavelengths(nm, [&](double l) { return ior.k(l); });
            d["name"] = ior.name();
            d["dispersive"] = ior.dispersive();
            return d;
        },
        py::arg("name"), py::arg("wavelengths"),
        "n and k of a named metal or glass or an n/k file at the wavelengths: a dict n, k, "
        "name, dispersive");
    m.def(
        "illuminant",
        [](const std::string& name, const DoubleArray& nm, double scale) {
            const EmissionSpectrum s = EmissionSpectrum::illuminant(name, scale);
            return overWavelengths(nm, [&](double l) { return s(l); });
        },
        py::arg("name"), py::arg("wavelengths"), py::arg("scale") = 1.0,
        "A CIE illuminant normalised to luminance Y = scale, as a scene's {\"illuminant\"}");
    m.def(
        "blackbody",
        [](double kelvin, const DoubleArray& nm, double scale) {
            if (!(kelvin > 0) || !std::isfinite(kelvin))
                throw py::value_error("kelvin: expected a positive temperature");
            const EmissionSpectrum s = EmissionSpectrum::blackbody(kelvin, scale);
            return overWavelengths(nm, [&](double l) { return s(l); });
        },
        py::arg("kelvin"), py::arg("wavelengths"), py::arg("scale") = 1.0,
        "Planck's law normalised to luminance Y = scale, as a scene's {\"blackbody\"}");
    m.def(
        "cie_cmf",
        [](const DoubleArray& nm) {
            py::array_t<double> x = overWavelengths(nm, cieX), y = overWavelengths(nm, cieY),
                                z = overWavelengths(nm, cieZ);
            return py::module_::import("numpy").attr("stack")(py::make_tuple(x, y, z), -1);
        },
        py::arg("wavelengths"), "CIE 1931 2-degree x-bar, y-bar, z-bar: shape (..., 3)");
    m.def(
        "xyz_to_rgb",
        [](const DoubleArray& xyz) {
            return vec3Rows(xyz, "xyz", RgbColorSpace::rec709().xyzToRgb());
        },
        py::arg("xyz"), "CIE XYZ -> linear Rec.709, (N, 3) or (3,)");
    m.def(
        "rgb_to_xyz",
        [](const DoubleArray& rgb) {
            return vec3Rows(rgb, "rgb", RgbColorSpace::rec709().rgbToXyz());
        },
        py::arg("rgb"), "Linear Rec.709 -> CIE XYZ, (N, 3) or (3,)");
    m.def(
        "rgb_to_spectrum",
        [](const std::array<double, 3>& rgb, const DoubleArray& nm, const std::string& kind) {
            const auto k = kRgbSpectrumKindNames.find(kind);
            if (!k)
                throw py::value_error("kind: expected one of " + kRgbSpectrumKindNames.list() +
                                      ", got \"" + kind + "\"");
            for (const double c : rgb)
                if (!(c >= 0) || !std::isfinite(c))
                    throw py::value_error("rgb: expected finite components >= 0");
            const RgbSpectrum s(Rgb<double>(rgb[0], rgb[1], rgb[2]), *k);
            return overWavelengths(nm, [&](double l) { return s(l); });
        },
        py::arg("rgb"), py::arg("wavelengths"), py::arg("kind") = "reflectance",
        "The smooth spectrum of a linear Rec.709 colour (Jakob and Hanika 2019) as spectral "
        "mode upsamples it: kind reflectance, unbounded or illuminant");
    m.def(
        "conductor_f0_f82",
        [](const std::string& name) {
            const auto [f0, f82] = conductorF0F82(iorOf(name));
            return py::make_tuple(rgbArray(f0), rgbArray(f82));
        },
        py::arg("name"),
        "RGB mode's reduction of a metal's n, k (Hoffman 2019): (F0, F82), linear Rec.709");
}

}  // namespace lamina::python
