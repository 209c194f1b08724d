// lamina.Material: one material of the JSON material reader (docs/bsdf.md), built as the
// command line's `lamina bsdf` builds it (double precision, local frame, directions
// normalised), evaluated over NumPy arrays with the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "arrays.h"
#include "bindings.h"
#include "lamina/bsdf/albedo_estimate.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/core/error.h"
#include "lamina/core/json_reader.h"
#include "lamina/core/mueller_matrix.h"
#include "lamina/render/renderer.h"
#include "lamina/scene/rgl_bsdf_file.h"

namespace lamina::python {

namespace {

using RgbD = Rgb<double>;
using SpectralD = SampledSpectrum<double>;
constexpr int kHero = SpectralD::kSize;  // wavelengths one spectral BSDF carries

/// A spectral BSDF and the wavelengths it was built for (the builder keeps a reference to
/// them: a dispersive glass terminates the secondary wavelengths).
struct SpectralBsdf {
    SampledWavelengths<double> lambda;
    std::unique_ptr<Bxdf<SpectralD>> bxdf;
};

std::unique_ptr<SpectralBsdf> buildSpectral(const MaterialDesc& desc,
                                            const std::array<double, kHero>& nm) {
    auto b = std::make_unique<SpectralBsdf>();
    b->lambda = SampledWavelengths<double>::fixed(nm);
    const SpectrumContext<SpectralD> context{b->lambda};
    b->bxdf = buildBxdf(desc, context);
    return b;
}

TransportMode transportMode(const std::string& name) {
    if (const auto t = kTransportModeNames.find(name)) return *t;
    throw py::value_error("transport: expected one of " + kTransportModeNames.list() + ", got \"" +
                          name + "\"");
}

class Material {
  public:
    Material(const py::object& spec, const std::string& mode) {
        if (const auto m = render::kRenderModeNames.find(mode))
            mode_ = *m;
        else
            throw py::value_error("mode: expected one of " + render::kRenderModeNames.list() +
                                  ", got \"" + mode + "\"");
        if (mode_ == render::RenderModeKind::Polarised)
            throw py::value_error(
                "mode: \"polarised\" renders scenes (lamina.render); a Material evaluates in "
                "\"rgb\" or \"spectral\" mode");
        if (py::isinstance<py::str>(spec)) {
            desc_ = parseMaterialArgument(spec.cast<std::string>());
        } else if (py::isinstance<py::dict>(spec)) {
            static const JsonSource source{"<material dict>", "."};
            desc_ = parseMaterial(
                JsonReader(parseJsonText(jsonText(spec, source.name), source), "", source));
        } else {
            throw py::type_error("Material: expected a dict or a string (JSON or \"@file.json\")");
        }
        render::loadMeasuredTables(desc_);
        if (mode_ == render::RenderModeKind::Rgb)
            rgb_ = buildBxdf(desc_, SpectrumContext<RgbD>{});
        else
            defaultSpectral_ = buildSpectral(desc_, {450, 550, 650, 650});
    }

    bool spectral() const { return mode_ == render::RenderModeKind::Spectral; }
    std::uint32_t flags() const {
        return spectral() ? defaultSpectral_->bxdf->flags() : rgb_->flags();
    }

    py::array_t<double> eval(const DoubleArray& wo, const DoubleArray& wi,
                             const std::optional<DoubleArray>& wavelengths,
                             const std::string& transport) const {
        const TransportMode t = transportMode(transport);
        const Rows o = rowsOf(wo, 3, "wo"), i = rowsOf(wi, 3, "wi");
        if (!spectral()) {
            if (wavelengths) throw py::value_error("wavelengths: only in spectral mode");
            const std::size_t n = commonCount({{&o, "wo"}, {&i, "wi"}});
            const auto vo = directions(o, n, "wo"), vi = directions(i, n, "wi");
            auto out = newDoubles({py::ssize_t(n), 3});
            double* f = out.mutable_data();
            {
                py::gil_scoped_release release;
                for (std::size_t k = 0; k < n; ++k) {
                    const RgbD v = rgb_->eval(at(vo, k), at(vi, k), t);
                    for (int c = 0; c < 3; ++c)
                        f[k * 3 + std::size_t(c)] = v[c];
                }
            }
            return out;
        }
        std::size_t n = 0, k = 0;
        return overWavelengths(o, i, wavelengths, n, k, {}, [&](auto& array) {
            double* f = array.mutable_data();
            return [f, k, t](std::size_t r, const Vec3d& out, const Vec3d& in, std::size_t offset,
                             const SpectralBsdf& b) {
                const SpectralD v = b.bxdf->eval(out, in, t);
                for (int c = 0; c < kHero && offset + std::size_t(c) < k; ++c) {
                    if (b.lambda.secondaryTerminated() && c > 0) break;
                    f[r * k + offset + std::size_t(c)] = v[c];
                }
            };
        });
    }

    /// The polarised mode's Mueller matrices (docs/polarisation.md): (N, k, 4, 4), each
    /// mapping the Stokes vector of light arriving along -wi (in the canonical frame of wi) to
    /// that leaving along wo (in wo's); [..., 0, 0] is eval()'s value.
    py::array_t<double> mueller(const DoubleArray& wo, const DoubleArray& wi,
                                const std::optional<DoubleArray>& wavelengths,
                                const std::string& transport) const {
        const TransportMode t = transportMode(transport);
        if (!spectral())
            throw py::value_error(
                "mueller: a Material in spectral mode (the polarised mode's matrices are "
                "per wavelength): Material(..., mode=\"spectral\")");
        const Rows o = rowsOf(wo, 3, "wo"), i = rowsOf(wi, 3, "wi");
        std::size_t n = 0, k = 0;
        return overWavelengths(o, i, wavelengths, n, k, {4, 4}, [&](auto& array) {
            double* f = array.mutable_data();
            return [f, k, t](std::size_t r, const Vec3d& out, const Vec3d& in, std::size_t offset,
                             const SpectralBsdf& b) {
                const MuellerMatrix<SpectralD> m = b.bxdf->evalMueller(out, in, t);
                for (int c = 0; c < kHero && offset + std::size_t(c) < k; ++c) {
                    if (b.lambda.secondaryTerminated() && c > 0) break;
                    double* cell = f + (r * k + offset + std::size_t(c)) * 16;
                    for (int row = 0; row < 4; ++row)
                        for (int column = 0; column < 4; ++column)
                            cell[row * 4 + column] = m(row, column)[c];
                }
            };
        });
    }

    py::array_t<double> pdf(const DoubleArray& wo, const DoubleArray& wi,
                            const std::optional<DoubleArray>& wavelengths) const {
        const Rows o = rowsOf(wo, 3, "wo"), i = rowsOf(wi, 3, "wi");
        const std::size_t n = commonCount({{&o, "wo"}, {&i, "wi"}});
        const auto vo = directions(o, n, "wo"), vi = directions(i, n, "wi");
        const auto spectralBsdf = sampledBsdf(wavelengths);
        const Bxdf<SpectralD>* s = spectralBsdf ? spectralBsdf->bxdf.get() : nullptr;
        auto out = newDoubles({py::ssize_t(n)});
        double* p = out.mutable_data();
        py::gil_scoped_release release;
        for (std::size_t k = 0; k < n; ++k)
            p[k] = s ? s->pdf(at(vo, k), at(vi, k)) : rgb_->pdf(at(vo, k), at(vi, k));
        return out;
    }

    py::dict sample(const DoubleArray& wo, const DoubleArray& uLobe, const DoubleArray& uDir,
                    const std::optional<DoubleArray>& wavelengths,
                    const std::string& transport) const {
        const TransportMode t = transportMode(transport);
        const Rows o = rowsOf(wo, 3, "wo"), uc = rowsOf(uLobe, 1, "u_lobe"),
                   u = rowsOf(uDir, 2, "u_dir");
        const std::size_t n = commonCount({{&o, "wo"}, {&uc, "u_lobe"}, {&u, "u_dir"}});
        const auto vo = directions(o, n, "wo");
        const auto spectralBsdf = sampledBsdf(wavelengths);
        const int channels = spectralBsdf ? sampledChannels(wavelengths) : 3;
        auto wi = newDoubles({py::ssize_t(n), 3}), weight = newDoubles({py::ssize_t(n), channels}),
             pdf = newDoubles({py::ssize_t(n)}), eta = newDoubles({py::ssize_t(n)});
        py::array_t<std::int8_t> lobe({py::ssize_t(n)});
        double *pWi = wi.mutable_data(), *pWeight = weight.mutable_data(),
               *pPdf = pdf.mutable_data(), *pEta = eta.mutable_data();
        std::int8_t* pLobe = lobe.mutable_data();
        {
            py::gil_scoped_release release;
            const auto store = [&](std::size_t k, const auto& s) {
                for (int c = 0; c < 3; ++c)
                    pWi[k * 3 + std::size_t(c)] = s ? double(s->wi[c]) : 0.0;
                for (int c = 0; c < channels; ++c)
                    pWeight[k * std::size_t(channels) + std::size_t(c)] =
                        s ? double(s->weight[c]) : 0.0;
                pPdf[k] = s ? double(s->pdf) : 0.0;
                pEta[k] = s ? double(s->eta) : 1.0;
                pLobe[k] = -1;
                if (s)
                    for (std::size_t e = 0; e < kLobeKindNames.entries().size(); ++e)
                        if (kLobeKindNames.entries()[e].value == s->flags)
                            pLobe[k] = std::int8_t(e);
            };
            for (std::size_t k = 0; k < n; ++k) {
                const double* ud = u.row(k);
                if (spectralBsdf)
                    store(k, spectralBsdf->bxdf->sample(at(vo, k), uc.value(k), {ud[0], ud[1]}, t));
                else
                    store(k, rgb_->sample(at(vo, k), uc.value(k), {ud[0], ud[1]}, t));
            }
        }
        py::dict d;
        d["wi"] = wi;
        d["weight"] = weight;
        d["pdf"] = pdf;
        d["lobe"] = lobeNames(lobe);
        d["eta"] = eta;
        d["valid"] = py::array(lobe).attr("__ge__")(0);
        return d;
    }

    py::dict albedo(const DoubleArray& cosThetaO, std::size_t samples, std::uint64_t seed,
                    const std::optional<DoubleArray>& wavelengths,
                    const std::string& transport) const {
        const TransportMode t = transportMode(transport);
        const Rows c = rowsOf(cosThetaO, 1, "cos_theta");
        const std::size_t n = c.count;
        for (std::size_t k = 0; k < n; ++k)
            if (!(c.value(k) >= 0 && c.value(k) <= 1))
                throw py::value_error("cos_theta: expected values in [0, 1]");
        if (samples < 1) throw py::value_error("samples: expected at least 1");
        const auto spectralBsdf = sampledBsdf(wavelengths);
        const int channels = spectralBsdf ? sampledChannels(wavelengths) : 3;
        auto reflection = newDoubles({py::ssize_t(n), channels}),
             transmission = newDoubles({py::ssize_t(n), channels}),
             standardError = newDoubles({py::ssize_t(n), channels});
        double *r = reflection.mutable_data(), *tr = transmission.mutable_data(),
               *se = standardError.mutable_data();
        {
            py::gil_scoped_release release;
            const auto store = [&](std::size_t k, const auto& e) {
                for (int ch = 0; ch < channels; ++ch) {
                    const std::size_t j = k * std::size_t(channels) + std::size_t(ch);
                    r[j] = e.reflection[ch];
                    tr[j] = e.transmission[ch];
                    se[j] = e.standardError[ch];
                }
            };
            // Seeds seed + 1, seed + 2, ... as `lamina bsdf albedo` for its angles 0.05, 0.1...
            for (std::size_t k = 0; k < n; ++k) {
                const std::uint64_t s = seed + k + 1;
                if (spectralBsdf)
                    store(k, estimateAlbedo(*spectralBsdf->bxdf, c.value(k), samples, s, t));
                else
                    store(k, estimateAlbedo(*rgb_, c.value(k), samples, s, t));
            }
        }
        py::dict d;
        d["reflection"] = reflection;
        d["transmission"] = transmission;
        d["stderr"] = standardError;
        return d;
    }

    std::vector<std::string> lobes() const {
        std::vector<std::string> out;
        for (const auto& e : kLobeKindNames.entries())
            if ((flags() & e.value) == e.value) out.emplace_back(e.name);
        return out;
    }

    py::dict info() const {
        py::dict d;
        d["type"] = desc_.type;
        d["mode"] = std::string(render::kRenderModeNames.name(mode_));
        d["lobes"] = lobes();
        d["description"] = describeLobes(flags());
        d["delta"] = isSpecular(flags());
        return d;
    }

  private:
    /// A spectral evaluation over N direction pairs at k wavelengths (shape (k,), shared, or
    /// (N, k)): an array of shape (N, k, *trailing), filled by the writer that `bind(array)`
    /// returns, called per row r with its directions, each BSDF and the offset of its first
    /// wavelength. n and k are set. The GIL is released while it runs.
    template <typename Bind>
    py::array_t<double> overWavelengths(const Rows& o, const Rows& i,
                                        const std::optional<DoubleArray>& wavelengths,
                                        std::size_t& n, std::size_t& k,
                                        const std::vector<py::ssize_t>& trailing, Bind bind) const {
        const DoubleArray nm = wavelengths ? *wavelengths : defaultWavelengths();
        if (nm.ndim() < 1 || nm.ndim() > 2 || nm.shape(nm.ndim() - 1) < 1)
            throw py::value_error("wavelengths: expected shape (k,) or (N, k)");
        k = std::size_t(nm.shape(nm.ndim() - 1));
        const Rows l = rowsOf(nm, k, "wavelengths");
        n = commonCount({{&o, "wo"}, {&i, "wi"}, {&l, "wavelengths"}});
        const auto vo = directions(o, n, "wo"), vi = directions(i, n, "wi");
        checkWavelengths(l);
        std::vector<py::ssize_t> shape{py::ssize_t(n), py::ssize_t(k)};
        shape.insert(shape.end(), trailing.begin(), trailing.end());
        auto out = newDoubles(shape);
        const auto write = bind(out);
        py::gil_scoped_release release;
        // One set of BSDFs for shared wavelengths, else one per row.
        std::vector<std::pair<std::size_t, std::unique_ptr<SpectralBsdf>>> bsdfs;
        for (std::size_t row = 0; row < (l.shared ? 1 : n); ++row) {
            bsdfs = bsdfsAt(l.row(row), k);
            const std::size_t first = l.shared ? 0 : row, last = l.shared ? n : row + 1;
            for (std::size_t r = first; r < last; ++r)
                for (const auto& [offset, b] : bsdfs)
                    write(r, at(vo, r), at(vi, r), offset, *b);
        }
        return out;
    }

    static DoubleArray defaultWavelengths() {
        DoubleArray a(3);
        double* p = a.mutable_data();
        p[0] = 450;
        p[1] = 550;
        p[2] = 650;
        return a;
    }

    static void checkWavelengths(const Rows& l) {
        const std::size_t total = l.shared ? l.width : l.count * l.width;
        for (std::size_t j = 0; j < total; ++j)
            if (!(l.data[j] >= kLambdaMin && l.data[j] <= kLambdaMax))
                throw py::value_error("wavelengths: expected values in [360, 830] nm, got " +
                                      std::to_string(l.data[j]));
    }

    /// BSDFs covering k wavelengths, four at a time (the last group padded with its last
    /// wavelength); a dispersive material, whose BSDF keeps only its hero wavelength, gets one
    /// BSDF per wavelength. Each with the offset of its first wavelength.
    std::vector<std::pair<std::size_t, std::unique_ptr<SpectralBsdf>>> bsdfsAt(
        const double* nm, std::size_t k) const {
        std::vector<std::pair<std::size_t, std::unique_ptr<SpectralBsdf>>> out;
        for (std::size_t first = 0; first < k;) {
            std::array<double, kHero> l{};
            for (std::size_t c = 0; c < std::size_t(kHero); ++c)
                l[c] = nm[std::min(first + c, k - 1)];
            auto b = buildSpectral(desc_, l);
            const std::size_t step = b->lambda.secondaryTerminated() ? 1 : std::size_t(kHero);
            out.emplace_back(first, std::move(b));
            first += step;
        }
        return out;
    }

    /// The spectral BSDF for sample/pdf/albedo (1 to 4 wavelengths; the first is the hero),
    /// nullptr in RGB mode.
    std::unique_ptr<SpectralBsdf> sampledBsdf(const std::optional<DoubleArray>& wavelengths) const {
        if (!spectral()) {
            if (wavelengths) throw py::value_error("wavelengths: only in spectral mode");
            return nullptr;
        }
        const DoubleArray nm = wavelengths ? *wavelengths : defaultWavelengths();
        if (nm.ndim() != 1 || nm.shape(0) < 1 || nm.shape(0) > kHero)
            throw py::value_error("wavelengths: expected 1 to 4 wavelengths, shape (k,)");
        const Rows l = rowsOf(nm, std::size_t(nm.shape(0)), "wavelengths");
        checkWavelengths(l);
        std::array<double, kHero> a{};
        for (std::size_t c = 0; c < std::size_t(kHero); ++c)
            a[c] = nm.data()[std::min<std::size_t>(c, std::size_t(nm.shape(0)) - 1)];
        return buildSpectral(desc_, a);
    }
    static int sampledChannels(const std::optional<DoubleArray>& wavelengths) {
        return wavelengths ? int(wavelengths->shape(0)) : 3;
    }

    static py::object lobeNames(const py::array_t<std::int8_t>& codes) {
        py::list names;
        for (const auto& e : kLobeKindNames.entries())
            names.append(std::string(e.name));
        names.append(std::string());  // code -1: absorbed
        const py::module_ np = py::module_::import("numpy");
        return np.attr("array")(names)[codes];
    }

    MaterialDesc desc_;
    render::RenderModeKind mode_ = render::RenderModeKind::Rgb;
    std::unique_ptr<Bxdf<RgbD>> rgb_;
    std::unique_ptr<SpectralBsdf> defaultSpectral_;
};

}  // namespace

void bindMaterial(py::module_& m) {
    py::class_<Material>(m, "Material",
                         "A material of the JSON material reader (docs/bsdf.md) in RGB or "
                         "spectral mode; directions in the local frame (z = normal)")
        .def(py::init<const py::object&, const std::string&>(), py::arg("material"),
             py::arg("mode") = "rgb")
        .def("eval", &Material::eval, py::arg("wo"), py::arg("wi"),
             py::arg("wavelengths") = py::none(), py::arg("transport") = "radiance",
             "f(wo, wi) |cos theta_i|: (N, 3) in RGB mode, (N, k) at the wavelengths")
        .def("mueller", &Material::mueller, py::arg("wo"), py::arg("wi"),
             py::arg("wavelengths") = py::none(), py::arg("transport") = "radiance",
             "The polarised mode's Mueller matrices (N, k, 4, 4) at the wavelengths, in the "
             "canonical frames of wi (in) and wo (out); [..., 0, 0] equals eval(). Spectral "
             "mode only")
        .def("pdf", &Material::pdf, py::arg("wo"), py::arg("wi"),
             py::arg("wavelengths") = py::none(), "Solid-angle density of sample(wo) at wi, (N,)")
        .def(
            "pdf_reverse",
            [](const Material& self, const DoubleArray& wo, const DoubleArray& wi,
               const std::optional<DoubleArray>& wavelengths) {
                return self.pdf(wi, wo, wavelengths);
            },
            py::arg("wo"), py::arg("wi"), py::arg("wavelengths") = py::none(),
            "pdf(wi, wo): the density of the reverse direction (BDPT)")
        .def("sample", &Material::sample, py::arg("wo"), py::arg("u_lobe"), py::arg("u_dir"),
             py::arg("wavelengths") = py::none(), py::arg("transport") = "radiance",
             "Draws wi: a dict of wi (N, 3), weight, pdf, lobe, eta, valid")
        .def("albedo", &Material::albedo, py::arg("cos_theta"), py::arg("samples") = 100000,
             py::arg("seed") = 0, py::arg("wavelengths") = py::none(),
             py::arg("transport") = "radiance",
             "Directional albedo: a dict of reflection, transmission, stderr (M, channels)")
        .def_property_readonly("lobes", &Material::lobes)
        .def("info", &Material::info);
}

}  // namespace lamina::python
