// Mitsuba <transform> elements -> the lamina transform operations (mitsuba_plugin.h). The
// operations follow mitsuba3 src/core/xml.cpp: each one applied after the previous.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "lamina/core/error.h"
#include "mitsuba_plugin.h"

namespace lamina::render::mitsuba {

namespace {

// Mitsuba's up for a lookat without one: the first vector of coordinate_system(dir)
// (mitsuba3 include/mitsuba/core/vector.h, Duff et al. 2017, "Building an orthonormal basis,
// revisited"), with sign(0) = 1.
glm::dvec3 mitsubaDefaultUp(const glm::dvec3& n) {
    const double sign = n.z >= 0 ? 1.0 : -1.0;
    const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    return {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

Json tripleJson(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

}  // namespace

Transform readTransform(const Element& transform) {
    Transform t;
    for (const Element& op : transform.children) {
        const std::string what = "<" + op.tag + ">";
        glm::dmat4 m(1.0);
        if (op.tag == "translate" || op.tag == "scale")
            checkAttributes(op, {"value", "x", "y", "z"});
        if (op.tag == "rotate") checkAttributes(op, {"value", "x", "y", "z", "angle"});
        if (op.tag == "matrix") checkAttributes(op, {"value"});
        if (op.tag == "lookat") checkAttributes(op, {"origin", "target", "up"});
        if (op.tag == "translate") {
            const glm::dvec3 v = readTriple(op, 0.0, what);
            m = glm::translate(glm::dmat4(1.0), v);
            t.operations.push_back({{"translate", tripleJson(v)}});
        } else if (op.tag == "scale") {
            const glm::dvec3 v = readTriple(op, 1.0, what);
            m = glm::scale(glm::dmat4(1.0), v);
            t.operations.push_back({{"scale", tripleJson(v)}});
        } else if (op.tag == "rotate") {
            const glm::dvec3 axis = readTriple(op, 0.0, what);
            const std::string* angle = op.attribute("angle");
            if (!angle) throw InputError(op.where() + ": <rotate> needs an angle (degrees)");
            const double degrees = parseNumber(*angle, op, what);
            if (glm::length(axis) == 0)
                throw InputError(op.where() + ": <rotate> needs a non-zero axis");
            m = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis));
            t.operations.push_back({{"rotate", {{"axis", tripleJson(axis)}, {"angle", degrees}}}});
        } else if (op.tag == "matrix") {
            const std::string* value = op.attribute("value");
            if (!value) throw InputError(op.where() + ": <matrix> needs a value (16 numbers)");
            const auto v = parseNumbers(*value, op, what);
            if (v.size() != 16 && v.size() != 9)
                throw InputError(op.where() + ": <matrix>: expected 16 or 9 numbers, got " +
                                 std::to_string(v.size()));
            const int n = v.size() == 16 ? 4 : 3;
            for (int row = 0; row < n; ++row)
                for (int col = 0; col < n; ++col)
                    m[col][row] = v[std::size_t(row * n + col)];
        } else if (op.tag == "lookat") {
            // mitsuba3 Transform::look_at: columns left = up x dir, up' = dir x left, dir, origin.
            const std::string* origin = op.attribute("origin");
            const std::string* target = op.attribute("target");
            if (!origin || !target)
                throw InputError(op.where() + ": <lookat> needs origin and target");
            const auto o = parseNumbers(*origin, op, "origin");
            const auto g = parseNumbers(*target, op, "target");
            std::vector<double> u = {0, 0, 0};
            if (const std::string* up = op.attribute("up")) u = parseNumbers(*up, op, "up");
            if (o.size() != 3 || g.size() != 3 || u.size() != 3)
                throw InputError(op.where() + ": <lookat>: origin, target and up take 3 numbers");
            const glm::dvec3 eye(o[0], o[1], o[2]), at(g[0], g[1], g[2]);
            glm::dvec3 up(u[0], u[1], u[2]);
            if (glm::length(at - eye) == 0)
                throw InputError(op.where() + ": <lookat>: target equals origin");
            const glm::dvec3 dir = glm::normalize(at - eye);
            if (glm::length(up) == 0) up = mitsubaDefaultUp(dir);
            const glm::dvec3 cross = glm::cross(up, dir);
            if (glm::length(cross) == 0)
                throw InputError(op.where() + ": <lookat>: up is parallel to the view direction");
            const glm::dvec3 left = glm::normalize(cross);
            const glm::dvec3 newUp = glm::cross(dir, left);
            m = glm::dmat4(glm::dvec4(left, 0), glm::dvec4(newUp, 0), glm::dvec4(dir, 0),
                           glm::dvec4(eye, 1));
        } else {
            throw InputError(op.where() + ": <" + op.tag + "> is not a transform operation " +
                             "(translate, rotate, scale, matrix, lookat)");
        }
        if (op.tag == "matrix" || op.tag == "lookat") {
            Json rows = Json::array();
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col)
                    rows.push_back(m[col][row]);
            t.operations.push_back({{"matrix", rows}});
        }
        t.matrix = m * t.matrix;  // each operation applies after the ones before it
    }
    return t;
}

}  // namespace lamina::render::mitsuba
