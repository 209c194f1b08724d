#include "rounded_rotation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lamina::render {

double columnSkew(const glm::dmat3& a) {
    double skew = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            const double li = glm::length(a[i]), lj = glm::length(a[j]);
            if (!(li > 0 && lj > 0)) return 1;  // a zero column: singular
            skew = std::max(skew, std::abs(glm::dot(a[i], a[j])) / (li * lj));
        }
    return skew;
}

double columnScaleError(const glm::dmat3& a) {
    double error = 0;
    for (int i = 0; i < 3; ++i)
        error = std::max(error, std::abs(glm::length(a[i]) - 1));
    return error;
}

glm::dmat3 orthonormalised(const glm::dmat3& a) {
    const glm::dvec3 z = glm::normalize(a[2]);
    const glm::dvec3 y = glm::normalize(a[1] - glm::dot(a[1], z) * z);
    const glm::dvec3 x = glm::cross(y, z);
    // cross(y, z) is x of a right-handed frame; a reflection keeps its sign.
    return glm::dmat3(glm::determinant(a) < 0 ? -x : x, y, z);
}

std::string deviationText(double deviation) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1e", deviation);
    return text;
}

}  // namespace lamina::render
