#include "declared_keywords.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <variant>

namespace lamina::python {

namespace {

using experiments::Data;
using experiments::OptionDecl;
using experiments::OptionKind;
using experiments::OptionValue;

[[noreturn]] void refuse(const OptionDecl& o, const std::string& expected) {
    throw py::value_error(o.python + ": expected " + expected);
}

bool isInteger(const py::handle& v) {
    return py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v);
}

bool isNumber(const py::handle& v) {
    return (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) &&
           !py::isinstance<py::bool_>(v);
}

// A str, or an os.PathLike for a file.
std::string textOf(const OptionDecl& o, const py::handle& v, bool path) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (path && py::hasattr(v, "__fspath__"))
        return py::module_::import("os").attr("fspath")(v).cast<std::string>();
    refuse(o, path ? "a file name" : "a text");
}

std::vector<std::string> listOf(const OptionDecl& o, const py::handle& v) {
    // A text list takes one str or path alone as the list of it: polarisation("scene.json").
    if (o.kind == OptionKind::TextList &&
        (py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__")))
        return {textOf(o, v, true)};
    if (!py::isinstance<py::list>(v) && !py::isinstance<py::tuple>(v)) refuse(o, "a list");
    std::vector<std::string> out;
    for (const py::handle item : v) {
        if (o.kind == OptionKind::NumberList && isNumber(item))
            out.push_back(py::str(item).cast<std::string>());  // its label: Python's repr
        else
            out.push_back(textOf(o, item, o.kind == OptionKind::TextList));
    }
    return out;
}

OptionValue valueOf(const OptionDecl& o, const py::handle& v) {
    switch (o.kind) {
        case OptionKind::Flag:
            return v.cast<bool>();
        case OptionKind::Integer: {
            if (!isInteger(v)) refuse(o, "an integer");
            const py::int_ i = py::reinterpret_borrow<py::int_>(v);
            if (i < py::int_(std::numeric_limits<long long>::min()) ||
                i > py::int_(std::numeric_limits<long long>::max()))
                refuse(o, "an integer in [" + std::to_string(o.minInteger) + ", " +
                              std::to_string(o.maxInteger) + "]");
            return i.cast<long long>();
        }
        case OptionKind::Number:
            if (!isNumber(v)) refuse(o, "a number");
            return v.cast<double>();
        case OptionKind::Text:
        case OptionKind::Name:
            return textOf(o, v, false);
        case OptionKind::File:
            return textOf(o, v, true);
        case OptionKind::NameList:
        case OptionKind::TextList:
        case OptionKind::NumberList:
            return listOf(o, v);
        case OptionKind::Resolution:
            if (py::isinstance<py::sequence>(v) && !py::isinstance<py::str>(v) && py::len(v) == 2) {
                const auto s = py::reinterpret_borrow<py::sequence>(v);
                if (isInteger(s[0]) && isInteger(s[1])) {
                    const auto side = [](const py::handle& x) {
                        const long long n = x.cast<long long>();
                        return n < 1 || n > std::numeric_limits<int>::max() ? 0 : int(n);
                    };
                    return std::pair{side(s[0]), side(s[1])};
                }
            }
            if (!py::isinstance<py::str>(v)) refuse(o, "(width, height) or \"WIDTHxHEIGHT\"");
            return OptionValue{};  // text: read as the command line reads it
        case OptionKind::Callback:
            break;
    }
    return OptionValue{};
}

std::string pythonKeywords(const experiments::CommandDecl& command) {
    std::string out;
    for (const OptionDecl& o : command.options)
        if (o.onPython() && !o.positional) out += (out.empty() ? "" : ", ") + o.python;
    return out;
}

py::object valueToPython(const OptionValue& v) {
    return std::visit(
        [](const auto& x) -> py::object {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::monostate>)
                return py::none();
            else if constexpr (std::is_same_v<T, std::vector<std::string>>)
                return py::cast(x);
            else if constexpr (std::is_same_v<T, std::pair<int, int>>)
                return py::make_tuple(x.first, x.second);
            else
                return py::cast(x);
        },
        v);
}

}  // namespace

experiments::OptionValues keywordValues(const experiments::CommandDecl& command,
                                        const py::dict& keywords, const std::string& function,
                                        std::map<std::string, py::object>* callbacks) {
    experiments::OptionValues values(command);
    for (const auto& [k, v] : keywords) {
        const std::string key = py::str(k);
        const OptionDecl* option = nullptr;
        for (const OptionDecl& o : command.options)
            if (o.onPython() && o.python == key) option = &o;
        if (!option)
            throw py::type_error(function + "() got an unexpected keyword argument '" + key +
                                 "'; expected " + pythonKeywords(command));
        if (v.is_none()) continue;
        try {
            if (option->kind == OptionKind::Callback) {
                if (!PyCallable_Check(v.ptr())) refuse(*option, "a callable");
                if (callbacks) (*callbacks)[option->name] = py::reinterpret_borrow<py::object>(v);
                continue;
            }
            const OptionValue value = valueOf(*option, v);
            if (std::holds_alternative<std::monostate>(value))
                values.setText(option->name, v.cast<std::string>());
            else
                values.set(option->name, value);
        } catch (const experiments::OptionError& e) {
            throw py::value_error(e.option().python + ": " + e.what());
        }
    }
    try {
        values.finish();
    } catch (const experiments::OptionError& e) {
        throw py::value_error(e.option().python + ": " + e.what());
    }
    return values;
}

py::list optionsData(const experiments::CommandDecl& command) {
    py::list out;
    for (const OptionDecl& o : command.options) {
        py::dict d;
        d["name"] = o.name;
        d["command_line"] = o.onCommandLine() ? py::cast(o.commandLineNames()) : py::none();
        d["python"] = o.onPython() ? py::cast(o.python) : py::none();
        d["kind"] = std::string(experiments::kOptionKindNames.name(o.kind));
        d["help"] = o.help;
        d["default"] = valueToPython(o.defaultValue);
        d["required"] = o.required;
        d["positional"] = o.positional;
        d["front_end"] = std::string(experiments::kFrontEndNames.name(o.frontEnd));
        d["difference"] = o.difference;
        d["names"] = o.names;
        if (o.kind == OptionKind::Integer)
            d["range"] = py::make_tuple(o.minInteger, o.maxInteger);
        else if (o.numberRange)
            d["range"] = py::make_tuple(o.numberRange->first, o.numberRange->second);
        else
            d["range"] = py::none();
        out.append(d);
    }
    return out;
}

py::object toPython(const Data& data) {
    return std::visit(
        [](const auto& x) -> py::object {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::monostate>) {
                return py::none();
            } else if constexpr (std::is_same_v<T, experiments::DataArray>) {
                std::vector<py::ssize_t> shape(x.shape.begin(), x.shape.end());
                if (x.integers) {
                    py::array_t<int> a(shape);
                    if (std::size_t(a.size()) != x.ints.size())
                        throw std::logic_error("an array's values do not fill its shape");
                    std::copy(x.ints.begin(), x.ints.end(), a.mutable_data());
                    return a;
                }
                py::array_t<double> a(shape);
                if (std::size_t(a.size()) != x.doubles.size())
                    throw std::logic_error("an array's values do not fill its shape");
                std::copy(x.doubles.begin(), x.doubles.end(), a.mutable_data());
                return a;
            } else if constexpr (std::is_same_v<T, Data::List>) {
                py::list l;
                for (const Data& item : x)
                    l.append(toPython(item));
                return l;
            } else if constexpr (std::is_same_v<T, Data::Dict>) {
                py::dict d;
                for (const experiments::DataEntry& e : x)
                    d[toPython(e.key)] = toPython(e.value);
                return d;
            } else {
                return py::cast(x);
            }
        },
        data.value());
}

}  // namespace lamina::python
