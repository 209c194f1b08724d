// NumPy arrays in and out of the module: inputs are converted once to C-contiguous float64
// (pybind11's forcecast), a row of width w is either one of N rows or a single row given
// alone (shape (w,), or a scalar when w = 1) that every row shares; outputs are allocated
// before the GIL is released so the loops that fill them touch no Python object.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "lamina/core/vector.h"

namespace lamina::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Rows of width `width` of an input array.
struct Rows {
    const double* data = nullptr;
    std::size_t count = 1;
    std::size_t width = 1;
    bool shared = true;  ///< one row for every index
    const double* row(std::size_t i) const { return data + (shared ? 0 : i * width); }
    double value(std::size_t i) const { return *row(i); }
};

/// Shape (N, width) or (width,) (or a scalar or shape (N,) when width is 1); ValueError
/// "`what`: expected an array of shape (N, width) ..." otherwise.
Rows rowsOf(const DoubleArray& a, std::size_t width, const std::string& what);

/// The number of rows of arguments that must agree (shared rows fit any count); ValueError
/// naming them when two counts differ.
std::size_t commonCount(std::initializer_list<std::pair<const Rows*, const char*>> rows);

/// The rows of directions, normalised (one when the rows are shared), or ValueError naming the
/// first that is zero or not finite.
std::vector<Vec3d> directions(const Rows& rows, std::size_t n, const char* what);
/// Direction i of `directions`' result (the shared one for every i).
inline const Vec3d& at(const std::vector<Vec3d>& v, std::size_t i) {
    return v.size() == 1 ? v[0] : v[i];
}

/// A new float64 array of the given shape.
inline py::array_t<double> newDoubles(const std::vector<py::ssize_t>& shape) {
    return py::array_t<double>(shape);
}

}  // namespace lamina::python
