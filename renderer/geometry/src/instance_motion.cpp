// An instance's transform at a time within the shutter: Embree 3 interpolates the matrices of
// an instance's two time steps linearly, element by element (not by a decomposition into
// rotation and translation, which pbrt-v4's AnimatedTransform uses); the hit is rebuilt with
// the same matrix, in double.
#include <glm/gtc/matrix_inverse.hpp>

#include "lamina/geometry/geometry.h"

namespace lamina::render {

namespace {

InstanceTransform fromMatrix(const glm::dmat4& toWorld) {
    InstanceTransform t;
    t.toWorld = toWorld;
    t.toObject = glm::inverse(t.toWorld);
    t.normalMatrix = glm::transpose(glm::inverse(glm::dmat3(t.toWorld)));
    t.mirrors = glm::determinant(glm::dmat3(t.toWorld)) < 0;
    return t;
}

}  // namespace

InstanceTransform InstanceTransform::fromEmbree(const float xfm[12]) {
    glm::dmat4 m(1.0);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 3; ++row)
            m[col][row] = double(xfm[col * 3 + row]);
    return fromMatrix(m);
}

InstanceTransform InstanceTransform::at(float time) const {
    if (!toWorldEnd) return *this;
    const double t = double(time);
    return fromMatrix((1.0 - t) * toWorld + t * *toWorldEnd);
}

}  // namespace lamina::render
