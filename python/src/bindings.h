// The parts of the lamina module, each defined in its own file and added to the module by
// module.cpp.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace lamina::python {

namespace py = pybind11;

void bindMaterial(py::module_& m);         // material_binding.cpp
void bindMaterialSupport(py::module_& m);  // material_support_binding.cpp
void bindSpectra(py::module_& m);          // spectra_binding.cpp
void bindRender(py::module_& m);           // render_binding.cpp
void bindExperiments(py::module_& m);      // experiments_binding.cpp

/// A Python dict (or any value json.dumps accepts) as JSON text; InputError naming `source`
/// and the JSON path of a NaN or infinite number (JSON has none).
std::string jsonText(const py::handle& value, const std::string& source);

}  // namespace lamina::python
