// `import lamina`: the BSDF lab, spectra and colour, rendering and the experiments over the
// same libraries as the command line (docs/python.md). Bad input is the command line's
// one-line InputError, raised as ValueError with the same text (file and JSON path).
#include <pybind11/pybind11.h>

#include <cmath>
#include <optional>

#include "bindings.h"
#include "lamina/core/error.h"
#include "lamina/core/json_reader.h"

namespace lamina::python {

namespace {

// The JSON path of the first NaN or infinite float in a dict of dicts and lists, as JsonReader
// writes paths ("base.reflectance[1]"). json.dumps would write it as the token NaN, which is no
// JSON, and the reader would report malformed JSON at a column of text the user never wrote.
std::optional<std::string> firstNonFinite(const py::handle& value, const std::string& path,
                                          int depth) {
    if (depth > kMaxJsonDepth) return std::nullopt;  // json.dumps reports a cycle itself
    if (py::isinstance<py::float_>(value)) {
        const double v = value.cast<double>();
        if (std::isfinite(v)) return std::nullopt;
        return (path.empty() ? std::string("(top level)") : path) +
               ": expected a finite number, got " +
               (std::isnan(v) ? "NaN"
                : v > 0       ? "infinity"
                              : "-infinity");
    }
    if (py::isinstance<py::dict>(value)) {
        for (const auto& [k, v] : value.cast<py::dict>()) {
            const std::string key = py::str(k).cast<std::string>();
            if (auto bad = firstNonFinite(v, path.empty() ? key : path + "." + key, depth + 1))
                return bad;
        }
    } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        std::size_t i = 0;
        for (const auto& v : value)
            if (auto bad = firstNonFinite(v, path + "[" + std::to_string(i++) + "]", depth + 1))
                return bad;
    }
    return std::nullopt;
}

}  // namespace

std::string jsonText(const py::handle& value, const std::string& source) {
    if (const auto bad = firstNonFinite(value, "", 0)) throw InputError(source + ": " + *bad);
    return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

}  // namespace lamina::python

PYBIND11_MODULE(_lamina, m) {
    namespace py = pybind11;
    m.doc() = "lamina: layered BSDFs, spectra, rendering and experiments (docs/python.md)";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const lamina::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    lamina::python::bindMaterial(m);
    lamina::python::bindMaterialSupport(m);
    lamina::python::bindSpectra(m);
    lamina::python::bindRender(m);
    lamina::python::bindExperiments(m);
}
