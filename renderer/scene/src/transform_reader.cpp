#include <glm/gtc/matrix_transform.hpp>

#include "lamina/scene/scene_readers.h"

namespace lamina::render {

// "transform": a list of operations applied in order (the first one first):
// {"translate": [x, y, z]}, {"scale": s | [x, y, z]}, {"rotate": {"axis": [x, y, z],
// "angle": degrees}}, {"matrix": [16 numbers, row-major]}.
Mat4 readTransform(const JsonReader& parent, const char* key) {
    Mat4 m(1.0);
    const auto t = parent.optionalChild(key);
    if (!t) return m;
    if (!t->value().is_array()) t->fail("expected an array of operations");
    for (std::size_t i = 0; i < t->value().size(); ++i) {
        const JsonReader op(t->value()[i], t->indexPath(i), t->source());
        op.expectObject();
        if (op.value().size() != 1)
            op.fail("expected one operation: translate, scale, rotate or matrix");
        Mat4 step(1.0);
        if (op.has("translate")) {
            step = glm::translate(Mat4(1.0), requiredVec3(op, "translate"));
        } else if (op.has("scale")) {
            const auto s = op.optionalTriple("scale");
            if ((*s)[0] == 0 || (*s)[1] == 0 || (*s)[2] == 0)
                op.failAt("scale", "a scale of 0 collapses the shape");
            step = glm::scale(Mat4(1.0), Vec3d((*s)[0], (*s)[1], (*s)[2]));
        } else if (op.has("rotate")) {
            const JsonReader rot = op.child("rotate");
            const Vec3d axis = requiredVec3(rot, "axis");
            if (glm::length(axis) == 0) rot.failAt("axis", "expected a non-zero axis");
            const double angle = rot.requiredNumber("angle");
            rot.finish();
            step = glm::rotate(Mat4(1.0), glm::radians(angle), glm::normalize(axis));
        } else if (op.has("matrix")) {
            step = requiredMatrix(op, "matrix");
            if (std::abs(glm::determinant(step)) < 1e-300) op.failAt("matrix", "is singular");
        } else {
            op.fail("expected one of translate, scale, rotate, matrix");
        }
        op.finish();
        m = step * m;
    }
    return m;
}

}  // namespace lamina::render
