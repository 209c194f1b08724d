// The module functions beside lamina.Material: the material types the scene reader knows (from
// their registrations, material_kind.h) and the random numbers `lamina bsdf sample` draws.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/core/pcg32.h"

namespace lamina::python {

void bindMaterialSupport(py::module_& m) {
    m.def(
        "random_numbers",
        [](std::size_t count, std::size_t dims, std::uint64_t seed) {
            auto out = newDoubles({py::ssize_t(count), py::ssize_t(dims)});
            Pcg32 rng(seed);
            double* p = out.mutable_data();
            for (std::size_t i = 0; i < count * dims; ++i)
                p[i] = rng.nextDouble();
            return out;
        },
        py::arg("count"), py::arg("dims") = 3, py::arg("seed") = 0,
        "Uniform numbers in [0, 1), (count, dims), row by row from PCG32(seed): the sequence "
        "`lamina bsdf sample --seed` draws (u_lobe, then u_dir) for each sample");
    m.def(
        "material_kinds",
        []() {
            const py::object loads = py::module_::import("json").attr("loads");
            py::list kinds;
            for (const MaterialKind* kind : materialKinds()) {
                py::dict d, texturable;
                d["name"] = std::string(kind->name);
                for (const TexturableKey& t : kind->texturable)
                    texturable[py::str(std::string(t.key))] =
                        std::string(kTexturedParameterNames.name(t.parameter));
                d["texturable"] = texturable;
                d["schema"] = loads(std::string(kind->schema));
                kinds.append(d);
            }
            return kinds;
        },
        "Every material type, as the scene reader knows it: a list of dicts of name, "
        "texturable (the keys a scene may take from a texture: 'color' or 'roughness') and "
        "schema (its branch of docs/scene.schema.json)");
}

}  // namespace lamina::python
