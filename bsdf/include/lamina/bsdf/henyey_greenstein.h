// The Henyey-Greenstein phase function (Henyey and Greenstein 1941, "Diffuse radiation in the
// galaxy", ApJ 93), in the medium of the coated material's slab. Directions are directions of
// propagation, so g > 0 scatters forward: p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5).
#pragma once

#include "lamina/core/frame.h"
#include "lamina/core/math.h"

namespace lamina {

template <std::floating_point T>
T henyeyGreenstein(T cosTheta, T g) {
    const T denom = T(1) + g * g - T(2) * g * cosTheta;
    return (T(1) - g * g) / (T(4) * kPi<T> * denom * std::sqrt(std::max(denom, T(0))));
}

/// A new propagation direction after scattering a photon travelling along `w`, with density
/// henyeyGreenstein(dot(w, result), g): the inverse of the phase function's CDF in cos theta.
template <std::floating_point T>
Vec3<T> sampleHenyeyGreenstein(const Vec3<T>& w, T g, const Vec2<T>& u) {
    T cosTheta;
    if (std::abs(g) < T(1e-3)) {
        cosTheta = T(1) - T(2) * u.x;
    } else {
        const T t = (T(1) - g * g) / (T(1) - g + T(2) * g * u.x);
        cosTheta = (T(1) + g * g - t * t) / (T(2) * g);
    }
    cosTheta = clamp(cosTheta, T(-1), T(1));
    const T sinTheta = safeSqrt(T(1) - cosTheta * cosTheta);
    const Vec3<T> local = sphericalDirection(sinTheta, cosTheta, T(2) * kPi<T> * u.y);
    return glm::normalize(Frame<T>::fromNormal(w).toWorld(local));
}

}  // namespace lamina
