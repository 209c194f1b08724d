// `import lamina`: the BSDF lab, spectra and colour, rendering and the experiments over the
// same libraries as the command line (docs/python.md). Bad input is the command line's
// one-line InputError, raised as ValueError with the same text (file and JSON path).
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "lamina/core/error.h"

namespace lamina::python {

std::string jsonText(const py::handle& value) {
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
    lamina::python::bindSpectra(m);
    lamina::python::bindRender(m);
    lamina::python::bindExperiments(m);
}
