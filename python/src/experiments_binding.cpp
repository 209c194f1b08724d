// The experiments in Python. Every experiment declared in experiments/ (command_declaration.h)
// is a function of the pure-Python layer (lamina/__init__.py), built from its declaration
// (command_options) and run by _run_experiment: the keywords are read as the command line's
// options are, the experiment runs with the GIL released, and its result (the declaration's
// `data`, no report) comes back as dicts, lists and NumPy arrays. compare measures arrays and
// Images rather than files, so it is bound here, with the declaration's keyword names.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <future>

#include "bindings.h"
#include "declared_keywords.h"
#include "lamina/experiments/command_declaration.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/interrupted.h"
#include "lamina/version.h"

namespace lamina::python {

namespace {

namespace ex = lamina::experiments;
/// An (H, W, 3) array, or an Image (its .rgb), as the RgbImage the metrics take.
render::RgbImage imageOf(const py::object& value, const char* what) {
    const py::object rgb = py::hasattr(value, "rgb") ? value.attr("rgb") : value;
    const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(rgb);
    if (!a || a.ndim() != 3 || a.shape(2) != 3)
        throw py::value_error(std::string(what) + ": expected an (H, W, 3) array or an Image");
    render::RgbImage img;
    img.height = int(a.shape(0));
    img.width = int(a.shape(1));
    img.pixels.assign(a.data(), a.data() + a.size());
    return img;
}

py::dict metricsDict(const ex::ImageMetrics& m) {
    py::dict d;
    for (const auto& e : ex::kMetricNames.entries())
        d[py::str(std::string(e.name))] = ex::metricValue(m, e.value);
    return d;
}

py::object compare(const py::object& a, const py::object& b,
                   const std::optional<std::string>& metric) {
    const render::RgbImage image = imageOf(a, "a"), reference = imageOf(b, "b");
    const ex::ImageMetrics m = ex::compareImages(image, reference);
    ex::requireComparedValues(m, image, "a", reference, "b");
    if (const std::string note = ex::nonFiniteNote(m); !note.empty())
        if (PyErr_WarnEx(PyExc_RuntimeWarning, note.c_str(), 1) != 0) throw py::error_already_set();
    if (!metric) return metricsDict(m);
    const auto e = ex::kMetricNames.find(*metric);
    if (!e)
        throw py::value_error("metric: expected one of " + ex::kMetricNames.list() + ", got \"" +
                              *metric + "\"");
    return py::float_(ex::metricValue(m, *e));
}

py::dict commandData(const ex::CommandDecl& c) {
    py::dict d;
    d["name"] = c.name;
    d["help"] = c.help;
    d["returns"] = c.returns;
    d["experiment"] = bool(c.data);
    return d;
}

py::object runExperiment(const std::string& name, const py::dict& keywords) {
    const ex::CommandDecl& command = ex::commandDeclaration(name);
    if (!command.data) throw py::value_error(name + " is not an experiment");
    const ex::OptionValues values = keywordValues(command, keywords, name);
    const ex::CommandContext context{{LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT}, {}};
    // The experiment runs on a thread of its own while this one, the caller's, looks for
    // Ctrl-C every 50 ms: Python delivers KeyboardInterrupt only to the thread that holds the
    // interpreter, and a call that kept the GIL released to its end would ignore Ctrl-C for
    // the whole run. On a signal the interrupt flag stops the experiment at its next check (a
    // render finishes its pass in flight; experiments/interrupted.h), and KeyboardInterrupt is
    // raised here: an experiment's numbers are whole or not at all, and the exception's .partial
    // holds what it had finished (Interrupted::partial; convergence's finished runs).
    std::atomic<bool>& interrupt = render::renderInterruptFlag();
    interrupt.store(false);
    // The result's arrays are NumPy's: imported now, not after a Ctrl-C (an import of a second
    // or so would delay the KeyboardInterrupt that carries a partial result).
    py::module_::import("numpy");
    std::future<ex::Data> running =
        std::async(std::launch::async, [&] { return command.data(values, context); });
    bool interrupted = false;
    while (true) {
        {
            py::gil_scoped_release release;
            if (running.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready) break;
        }
        if (PyErr_CheckSignals() != 0) {
            interrupted = true;
            interrupt.store(true);
            py::gil_scoped_release release;
            running.wait();
            break;
        }
    }
    ex::Data result;
    try {
        result = running.get();
    } catch (const ex::Interrupted& stopped) {
        interrupt.store(false);
        if (!interrupted) throw;
        // The KeyboardInterrupt PyErr_CheckSignals set, with what the experiment had done.
        py::error_already_set keyboardInterrupt;
        if (stopped.partial) keyboardInterrupt.value().attr("partial") = toPython(*stopped.partial);
        throw keyboardInterrupt;
    }
    interrupt.store(false);
    if (interrupted) throw py::error_already_set();
    return toPython(result);
}

}  // namespace

void bindExperiments(py::module_& m) {
    m.def(
        "commands",
        [] {
            py::list out;
            for (const ex::CommandDecl& c : ex::commandDeclarations())
                out.append(commandData(c));
            return out;
        },
        "The commands both front ends have: name, help, returns, experiment");
    m.def(
        "command_options",
        [](const std::string& name) { return optionsData(ex::commandDeclaration(name)); },
        py::arg("command"),
        "A command's declared options: name, command_line, python, kind, help, default, "
        "required, positional, front_end, difference, names, range");
    m.def("_run_experiment", &runExperiment, py::arg("command"), py::arg("keywords"));
    // py::arg keeps the name's pointer: the declarations live as long as the process.
    const ex::CommandDecl& c = ex::commandDeclaration("compare");
    m.def("compare", &compare, py::arg(c.option("image").python.c_str()),
          py::arg(c.option("reference").python.c_str()),
          py::arg(c.option("metric").python.c_str()) = py::none(),
          "Error metrics of a against the reference (relMSE epsilon 1e-2): one value, or a "
          "dict of mse, rmse, relmse, mae, max");
}

}  // namespace lamina::python
