// Whether four points are the corners of a rectangle, in order around it: what a portal
// (portal_environment.h) must be, checked where a scene is read and where pbrt-v4's portals
// are imported, so both refuse the same shapes with the same words.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "lamina/core/vector.h"

namespace lamina {

/// Nothing for a rectangle; otherwise what is wrong. pbrt-v4's tolerance: opposite sides
/// parallel and adjacent sides perpendicular to within 1e-3 in their cosines.
inline std::optional<std::string> whyNotARectangle(const std::array<Vec3<double>, 4>& c) {
    std::array<Vec3<double>, 4> side;  // c0 -> c1, c1 -> c2, c3 -> c2, c0 -> c3
    const int from[4] = {0, 1, 3, 0}, to[4] = {1, 2, 2, 3};
    for (int k = 0; k < 4; ++k) {
        const Vec3<double> d = c[std::size_t(to[k])] - c[std::size_t(from[k])];
        const double length = glm::length(d);
        if (!(length > 0) || !std::isfinite(length))
            return "corners " + std::to_string(from[k]) + " and " + std::to_string(to[k]) +
                   " coincide: expected a rectangle";
        side[std::size_t(k)] = d / length;
    }
    if (std::abs(glm::dot(side[0], side[2]) - 1) > 1e-3 ||
        std::abs(glm::dot(side[3], side[1]) - 1) > 1e-3 ||
        std::abs(glm::dot(side[0], side[1])) > 1e-3 || std::abs(glm::dot(side[0], side[3])) > 1e-3)
        return std::string(
            "expected a rectangle, corners in order around it (opposite sides parallel, sides "
            "perpendicular, within 1e-3)");
    return std::nullopt;
}

}  // namespace lamina
