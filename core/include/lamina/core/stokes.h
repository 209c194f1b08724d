// lamina's polarisation convention, in one place. docs/polarisation.md explains it with
// figures and derives the Fresnel amplitudes' signs and the reciprocity relation from it; every
// Mueller matrix in lamina assumes what this header states.
//
// A Stokes vector belongs to a ray travelling along the unit direction d (the direction the
// light propagates, whichever way a path was built) and to a reference frame: a unit vector x
// perpendicular to d, and y = d x x, so that (x, y, d) is right-handed. With the complex
// amplitudes E_x, E_y of the electric field (time dependence exp(-i omega t)):
//   S0 = |E_x|^2 + |E_y|^2                    the radiance
//   S1 = |E_x|^2 - |E_y|^2                    > 0: linear along x, < 0: along y
//   S2 = 2 Re(E_x conj(E_y))                  > 0: linear along (x + y)/sqrt 2
//   S3 = -2 Im(E_x conj(E_y))                 > 0: the field turns from x towards y, a
//                                               right-handed turn about d (thumb along d)
// Seen by an observer looking into the beam (d towards the eye, x to the right, y up), S3 > 0
// turns counter-clockwise. That is "right-circular" in the IEEE convention and "left-circular"
// in Born and Wolf's; lamina names neither and states the turn.
//
// Changing the frame: when x' = cos(phi) x + sin(phi) y (a turn by phi about d), the same light
// has S1' = cos(2 phi) S1 + sin(2 phi) S2 and S2' = -sin(2 phi) S1 + cos(2 phi) S2 (stokesRotation
// in mueller_matrix.h). A Mueller matrix maps a Stokes vector in its input frame to one in its
// output frame, so a path multiplies each vertex's matrix between rotations that carry one
// vertex's output frame into the next vertex's input frame.
#pragma once

#include <array>
#include <cmath>

#include "lamina/core/frame.h"
#include "lamina/core/vector.h"

namespace lamina {

/// S0..S3; the elements are numbers or spectra (one Stokes vector per wavelength).
template <typename T>
using StokesVector = std::array<T, 4>;

/// Unpolarised light of radiance `s0`.
template <std::floating_point T>
constexpr StokesVector<T> unpolarisedStokes(T s0) {
    return {s0, T(0), T(0), T(0)};
}

/// The degree of polarisation sqrt(S1^2 + S2^2 + S3^2) / S0 (0 for S0 = 0).
template <std::floating_point T>
T degreeOfPolarisation(const StokesVector<T>& s) {
    if (s[0] <= T(0)) return T(0);
    // Divided first: the squares of a dim pixel's components would underflow.
    const T a = s[1] / s[0], b = s[2] / s[0], c = s[3] / s[0];
    return std::sqrt(a * a + b * b + c * c);
}

/// The degree of linear polarisation sqrt(S1^2 + S2^2) / S0 (0 for S0 = 0).
template <std::floating_point T>
T degreeOfLinearPolarisation(const StokesVector<T>& s) {
    if (s[0] <= T(0)) return T(0);
    return std::hypot(s[1] / s[0], s[2] / s[0]);
}

/// The angle of linear polarisation from x towards y, in (-pi/2, pi/2]: atan2(S2, S1) / 2.
template <std::floating_point T>
T angleOfLinearPolarisation(const StokesVector<T>& s) {
    return T(0.5) * std::atan2(s[2], s[1]);
}

/// The frame of a ray: its direction and its x axis (y = d x x).
template <std::floating_point T>
struct StokesFrame {
    Vec3<T> d;  ///< propagation direction, unit
    Vec3<T> x;  ///< reference axis, unit, perpendicular to d

    Vec3<T> y() const { return glm::cross(d, x); }
};

/// The reference axis every polarised computation uses for a direction it has no other frame
/// for: the tangent of the orthonormal basis around d (Frame::fromNormal, Duff et al. 2017).
/// Only consistency matters: a BSDF expresses its Mueller matrices in these frames of its local
/// directions, and the polarised mode turns them into these frames of the world directions,
/// so that the matrices of consecutive vertices meet in the same frame.
template <std::floating_point T>
Vec3<T> stokesAxis(const Vec3<T>& d) {
    return Frame<T>::fromNormal(d).s;
}

/// The angle phi by which `from`'s x axis turns about the shared direction to reach `to`'s
/// (right-handed about d): x_to = cos(phi) x_from + sin(phi) y_from.
template <std::floating_point T>
T frameTurn(const StokesFrame<T>& from, const Vec3<T>& toX) {
    return std::atan2(glm::dot(toX, from.y()), glm::dot(toX, from.x));
}

/// cos(2 phi) and sin(2 phi) of a frame turn phi: what a Stokes vector's S1, S2 rotate by.
template <std::floating_point T>
struct DoubledTurn {
    T c = T(1), s = T(0);

    static DoubledTurn of(T phi) { return {std::cos(T(2) * phi), std::sin(T(2) * phi)}; }
};

/// frameTurn's doubled angle without trigonometry (the hot path of every polarised event):
/// with a = cos(phi) |toX'|, b = sin(phi) |toX'| the projections of toX on from's axes,
/// cos(2 phi) = (a^2 - b^2) / (a^2 + b^2) and sin(2 phi) = 2ab / (a^2 + b^2), the double-angle
/// identities; a toX without a projection (zero) turns by 0 as atan2(0, 0) does.
template <std::floating_point T>
DoubledTurn<T> doubledFrameTurn(const StokesFrame<T>& from, const Vec3<T>& toX) {
    const T a = glm::dot(toX, from.x), b = glm::dot(toX, from.y());
    const T r = a * a + b * b;
    if (!(r > T(0))) return {};
    return {(a * a - b * b) / r, T(2) * a * b / r};
}

/// The s axis of an interaction: the unit normal of the plane of incidence spanned by the
/// direction d and the (micro)surface normal n, as d x n normalised. When d is parallel to n
/// every plane contains both and any perpendicular axis serves: `fallback` (perpendicular to
/// n) is taken, so that the result stays a function of the inputs.
template <std::floating_point T>
Vec3<T> planeOfIncidenceNormal(const Vec3<T>& d, const Vec3<T>& n, const Vec3<T>& fallback) {
    const Vec3<T> s = glm::cross(d, n);
    const T length2 = glm::dot(s, s);
    if (length2 < T(1e-12)) return fallback;
    return s / std::sqrt(length2);
}

}  // namespace lamina
