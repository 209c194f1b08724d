// Python's side of the commands declared in experiments/ (command_declaration.h): keyword
// arguments read as the declaration's option values, the declarations themselves as Python
// data (the pure-Python layer builds the experiments' functions and signatures from them), and
// an experiment's result (Data) as dicts, lists and NumPy arrays.
#pragma once

#include <pybind11/pybind11.h>

#include <map>
#include <string>

#include "lamina/experiments/command_declaration.h"

namespace lamina::python {

namespace py = pybind11;

/// The keywords of `function` (Python spellings) as the values of `command`'s options; the
/// callables of its callback options go into `callbacks` by option name. A keyword the
/// declaration lacks for Python is a TypeError listing those it has; a value it refuses, a
/// ValueError naming the keyword. None leaves an option unset.
experiments::OptionValues keywordValues(const experiments::CommandDecl& command,
                                        const py::dict& keywords, const std::string& function,
                                        std::map<std::string, py::object>* callbacks = nullptr);

/// A declaration's options as a list of dicts (name, python, kind, help, default, required,
/// positional, front_end, difference, names, range).
py::list optionsData(const experiments::CommandDecl& command);

py::object toPython(const experiments::Data& data);

}  // namespace lamina::python
