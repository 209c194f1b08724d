#include "arrays.h"

#include <cmath>

namespace lamina::python {

Rows rowsOf(const DoubleArray& a, std::size_t width, const std::string& what) {
    Rows r;
    r.data = a.data();
    r.width = width;
    const auto w = py::ssize_t(width);
    if (a.ndim() == 2 && a.shape(1) == w) {
        r.count = std::size_t(a.shape(0));
        r.shared = false;
    } else if (a.ndim() == 1 && a.shape(0) == w) {
        r.count = 1;
    } else if (width == 1 && a.ndim() == 1) {
        r.count = std::size_t(a.shape(0));
        r.shared = false;
    } else if (width == 1 && a.ndim() == 0) {
        r.count = 1;
    } else {
        std::string shape = "(";
        for (py::ssize_t d = 0; d < a.ndim(); ++d)
            shape += (d ? ", " : "") + std::to_string(a.shape(d));
        shape += a.ndim() == 1 ? ",)" : ")";
        throw py::value_error(what + ": expected an array of shape " +
                              (width == 1 ? std::string("(N,)")
                                          : "(N, " + std::to_string(width) + ") or (" +
                                                std::to_string(width) + ",)") +
                              ", got shape " + shape);
    }
    return r;
}

std::size_t commonCount(std::initializer_list<std::pair<const Rows*, const char*>> rows) {
    std::size_t n = 1;
    const char* from = nullptr;
    for (const auto& [r, name] : rows) {
        if (r->shared) continue;
        if (from && r->count != n)
            throw py::value_error(std::string(name) + " has " + std::to_string(r->count) +
                                  " rows but " + from + " has " + std::to_string(n));
        n = r->count;
        from = name;
    }
    return n;
}

namespace {

Vec3d direction(const Rows& rows, std::size_t i, const char* what) {
    const double* p = rows.row(i);
    const Vec3d d(p[0], p[1], p[2]);
    const double length = glm::length(d);
    if (!(length > 0) || !std::isfinite(length))
        throw py::value_error(std::string(what) + "[" + std::to_string(rows.shared ? 0 : i) +
                              "]: expected a finite direction that is not zero");
    return glm::normalize(d);
}

}  // namespace

std::vector<Vec3d> directions(const Rows& rows, std::size_t n, const char* what) {
    std::vector<Vec3d> out(rows.shared ? 1 : n);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = direction(rows, i, what);
    return out;
}

}  // namespace lamina::python
